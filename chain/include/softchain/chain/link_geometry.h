#pragma once
// LinkGeometry: the chain's links as the pressure shapes them. Rigid links
// between the reference joint centres cannot follow a finger whose material
// stretches and shears where it is not a beam: near the clamp the cavity's
// end wall shears the layer the joints sit on, and the tip's end cap bulges
// out (measured on P10 in docs/chain_fidelity.md, "Links that follow the
// pressure"). The reduction therefore measures, per pressure sample, the
// link geometry U_i(p), U_T(p): the joint and tip positions at zero angles
// from which the chain, turned by the FEM's own angles, lands on the FEM's
// deformed joint centres and tip (KinematicChain), and the tip face's frame
// in the last link's frame, Q_T(p) (a rotation vector). Between the sampled
// pressures U is interpolated linearly, and held beyond the last one; the
// rest row (p = 0) is the reference geometry.
#include <softchain/chain/kinematic_chain.h>
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace softchain::chain
{
  class LinkGeometry
  {
  public:
    using PointInPressure = std::array<PiecewiseLinear, 3>; // x, y, z against pressure

    // One table per joint, the tip's, and the tip frame's rotation vector
    // (rad) in the last link's frame.
    LinkGeometry(std::vector<PointInPressure> joints, PointInPressure tip, PointInPressure tip_frame);

    int n_joints() const { return static_cast<int>(joints_.size()); }
    // The tabulated pressures of every point's table (sorted, unique): U(p)
    // is linear between consecutive ones.
    std::vector<double> table_pressures() const;
    // `reference` with the link geometry at `pressure`; std::invalid_argument
    // if the joint counts differ or the interpolated points are out of order.
    KinematicChain at(double pressure, const KinematicChain &reference) const;
    // The same into `chain`, a copy of the reference, without allocating.
    void apply(double pressure, KinematicChain &chain) const;

  private:
    std::vector<PointInPressure> joints_;
    PointInPressure              tip_;
    PointInPressure              tip_frame_;
  };
} // namespace softchain::chain
