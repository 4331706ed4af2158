#pragma once
// JointTables: a chain's joints as the reduction's files give them, before
// they become a ChainModel: centres J_i, k per joint and axis, optionally
// k(p) per axis, J_p(p) per joint and axis, and the links' geometry in
// pressure (LinkGeometry).
//
// Twist axes: joint i twists about the proximal link's x axis through S_i
// and bends about J_i. Where S_i != J_i, with_twist_joints makes it two
// spherical joints of the chain: a twist joint at S_i (moved 1 nm towards
// the base along x, which leaves its twist axis, parallel to x, where it
// is) free about psi only, then the bending joint at J_i free about theta
// and phi only; the other axes are held rigid (k = `rigid`, 1e6 x the
// largest k of the axis). The twist joint takes k_psi and J_p,x (the
// reduction's torque about S_i), the bending joint k_theta, k_phi and
// J_p,y, J_p,z.
#include <softchain/chain/chain_model.h>
#include <softchain/chain/link_geometry.h>
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
    std::vector<Eigen::Vector3d>                stiffness;     // (k_psi, k_theta, k_phi) per joint
    std::array<std::vector<PiecewiseLinear>, 3> k_in_pressure; // per axis, one per joint; empty: constant
    std::vector<PiecewiseLinear>                pressure_torque; // J_p(p), 3 per joint
    std::vector<bool>                           twist_joints;    // empty: none
    std::optional<LinkGeometry>                 link_geometry;   // none: rigid reference links

    // The joints with twist axes through `twist_points` (one per joint);
    // *this when every S_i = J_i.
    JointTables with_twist_joints(const std::vector<Eigen::Vector3d> &twist_points,
                                  const Eigen::Vector3d              &rigid) const;

    // The chain to the tip point `tip`; J_p(p) and the link geometry from
    // the tables when `pressure_tables`, else the rest J_p (p = 0) and rigid
    // links between the reference centres.
    ChainModel model(const std::string &name, const Eigen::Vector3d &tip, bool pressure_tables) const;
  };
} // namespace softchain::chain
