#pragma once
// LinkShiftPerTurn: links that lengthen (and rise) as their joint turns in
// the finger's plane away from the pressure-only state. An inflated finger
// straightened by an obstacle against its pressure lengthens: on P10 at
// 50 kPa, blocked by a table, the links from joint 3 to joint 7 grow by
// 0.4-0.5 mm, which no joint of rigid links can follow
// (docs/chain_fidelity.md, "Links that follow the pressure"). The reduction
// measures each link's shift per radian of its joint's in-plane turn,
// g_i(p) in the link's frame (x along the finger, y towards the top), on the
// in-plane force samples (reduction/README.md, "The links' shift per turn").
// The chain interpolates g_i(p) linearly between the fitted pressures and
// holds it beyond (PiecewiseLinear), and moves link i by R_i g_i (phi_i -
// phi_i^p) about the pressure-only angle phi_i^p = J_p,phi,i p / k_phi,i(p)
// (KinematicChain::assign_link_shift): the pressure-only state is unchanged.
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace softchain::chain
{
  class LinkShiftPerTurn
  {
  public:
    using ShiftInPressure = std::array<PiecewiseLinear, 2>; // g_x, g_y against pressure, m/rad

    // One table pair per link (joint i to joint i+1, the last to the tip);
    // std::invalid_argument if none or a value is not finite.
    explicit LinkShiftPerTurn(std::vector<ShiftInPressure> links);

    int n_links() const { return static_cast<int>(links_.size()); }
    // g_i(p) as (g_x, g_y, 0), m/rad.
    Eigen::Vector3d at(double pressure, int link) const;
    std::vector<double> table_pressures() const;

  private:
    std::vector<ShiftInPressure> links_;
  };
} // namespace softchain::chain
