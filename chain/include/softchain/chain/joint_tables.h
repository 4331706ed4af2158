#pragma once
// JointTables: a chain's joints as the reduction's files give them, before
// they become a ChainModel: centres J_i, the twist axis points S_i, k per
// joint and axis, optionally k(p) per axis, J_p(p) per joint and axis, and
// the links' geometry in pressure (LinkGeometry) and their series compliance
// c(p) (LinkCompliance), and the joints' response to forces (JointForceLaw).
//
// Twist axes: joint i twists (psi) about the proximal link's x axis through
// S_i and bends (theta, phi) about J_i (KinematicChain::with_twist_offsets);
// k_psi and J_p,x are the reduction's stiffness and pressure torque about
// S_i. Without twist points every joint is spherical about J_i.
#include <softchain/chain/chain_model.h>
#include <softchain/chain/link_geometry.h>
#include <softchain/chain/link_shift_per_turn.h>
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace softchain::chain
{
  struct JointTables
  {
    std::vector<Eigen::Vector3d>                joint_centres;
    std::vector<Eigen::Vector3d>                twist_points;  // S_i; empty: J_i
    std::vector<Eigen::Vector3d>                stiffness;     // (k_psi, k_theta, k_phi) per joint
    std::array<std::vector<PiecewiseLinear>, 3> k_in_pressure; // per axis, one per joint; empty: constant
    std::vector<PiecewiseLinear>                pressure_torque; // J_p(p), 3 per joint
    std::optional<LinkGeometry>                 link_geometry;   // none: rigid reference links
    std::optional<LinkShiftPerTurn>             link_shift;      // g_i(p), m/rad; none: links do not shift as joints turn
    std::optional<PiecewiseLinear>              link_compliance; // c(p), m/N; none: links rigid under forces
    std::optional<PiecewiseLinear>              skin_compliance; // c_s(p), m/N; none: rigid sections
    std::optional<PiecewiseLinear>              skin_shear_compliance; // c_t(p), m/N; none: sections rigid in shear
    std::optional<JointForceLaw>                force_law;       // none: linear springs about the pressure state

    // The chain to the tip point `tip`; J_p(p), the link geometry and the
    // link compliance from the tables when `pressure_tables`, else the rest
    // J_p (p = 0) and rigid links between the reference centres.
    ChainModel model(const std::string &name, const Eigen::Vector3d &tip, bool pressure_tables) const;
  };
} // namespace softchain::chain
