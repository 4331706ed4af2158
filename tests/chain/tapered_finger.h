#pragma once
// The fingers of the MuJoCo tests: a tapered 9-joint finger with all three
// J_p components (every hinge driven), and the same finger with K(p),
// J_p(p) and links shaped by p, twisting about axes above its joints.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/mujoco_quasi_static.h>

#include <catch2/catch.hpp>

namespace softchain::chain::testing
{
  // Joint centres dropping in y, stiffness and J_p varying along it.
  inline ChainModel tapered_finger()
  {
    std::vector<Eigen::Vector3d> joints, k;
    Eigen::VectorXd              jp(27);
    for (int i = 0; i < 9; ++i)
      {
        joints.emplace_back((i + 0.5) * 0.01, -0.0004 * i, 0.0);
        k.push_back((1.0 - 0.05 * i) * Eigen::Vector3d(0.2, 0.05, 0.05));
        jp.segment<3>(3 * i) = (1.0 - 0.03 * i) * Eigen::Vector3d(1e-8, -2e-8, 2e-7);
      }
    return ChainModel("tapered", KinematicChain(joints, {0.09, -0.0036, 0.0}), JointStiffness(k),
                      PressureActuation(jp));
  }

  // The tapered finger with k_phi falling linearly to 0.6 of its rest value
  // at p_max, J_p rising to 1.6 times the rest one at 0.4 p_max and falling
  // back to 1.3 times at p_max (a kink inside the range), its links
  // stretching by 3 % and sinking by 0.2 mm per joint at p_max, and twist
  // axes 3 mm above the joints: nothing about it is constant in p.
  inline ChainModel tapered_finger_in_pressure(const double p_max)
  {
    const ChainModel             base = tapered_finger();
    JointStiffness               k    = base.stiffness();
    std::vector<PiecewiseLinear> k_phi, jp;
    for (int i = 0; i < 9; ++i)
      k_phi.emplace_back(std::vector<double>{0, p_max}, std::vector<double>{k.joint(i)[2], 0.6 * k.joint(i)[2]});
    k.set_in_pressure(2, k_phi);
    const Eigen::VectorXd rest = base.actuation().rest_torque_per_pascal();
    for (Eigen::Index j = 0; j < rest.size(); ++j)
      jp.emplace_back(std::vector<double>{0, 0.4 * p_max, p_max},
                      std::vector<double>{rest[j], 1.6 * rest[j], 1.3 * rest[j]});
    PressureActuation actuation(rest);
    actuation.set_torque_in_pressure(jp);
    ChainModel model("in pressure",
                     base.chain().with_twist_offsets(std::vector<Eigen::Vector3d>(9, {0.0, 0.003, 0.0})), k,
                     actuation);
    const auto stretched = [&](const Eigen::Vector3d &X, const double sink) {
      const Eigen::Vector3d at_p_max = 1.03 * X - Eigen::Vector3d(0, sink, 0);
      const auto line = [&](const int c) { return PiecewiseLinear({0, p_max}, {X(c), at_p_max(c)}); };
      return LinkGeometry::PointInPressure{line(0), line(1), line(2)};
    };
    std::vector<LinkGeometry::PointInPressure> joints;
    for (int i = 0; i < 9; ++i)
      joints.push_back(stretched(base.chain().joint_centre(i), 2e-4 * i));
    const PiecewiseLinear zero({0}, {0});
    model.set_link_geometry(LinkGeometry(joints, stretched(base.chain().tip(), 2e-3), {zero, zero, zero}));
    return model;
  }

  // Tolerance: the chain's Newton tolerance 1e-10 (relative residual) gives
  // angles to ~1e-10 of their size (0.2 rad); MuJoCo's rest criterion adds
  // 1e-12 rad (MujocoQuasiStatic): 1e-10 rad per hinge, and 9 hinges times
  // 0.1 m arm bound the tip position error by 1e-10 m.
  inline void check_same_pose(const MujocoRestPose &mujoco, const Equilibrium &e, const ChainPose &pose)
  {
    CHECK((mujoco.angles - e.angles).cwiseAbs().maxCoeff() < 1e-10);
    CHECK((mujoco.tip - pose.tip_position).norm() < 1e-10);
  }
} // namespace softchain::chain::testing
