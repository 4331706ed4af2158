// MJCF export: the structure of the file, and plain MuJoCo itself: loaded,
// driven by the same pressure and tip force with gravity off and stepped
// with damping to rest, it must find the chain solver's pose (at p* for a
// chain that changes with p; mujoco_pressure_actuation_test.cc sets MuJoCo
// to every pressure).
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/mjcf_export.h>

#include "../data/occurrences.h"
#include "../data/scratch_directory.h"
#include "reduction_output.h"
#include "tapered_finger.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
namespace data = softchain::data;
using namespace softchain::chain::testing;

namespace
{
  // The uniform finger of the reduction's files with twist axes 4 mm above
  // its joints.
  ChainModel twist_axis_finger(const softchain::testing::ScratchDirectory &dir)
  {
    softchain::chain::testing::UniformReduction r;
    r.twist_height = 0.004;
    r.jp           = {0.0, 0.0, 2e-7};
    const StiffnessFiles files(dir.path().string(), data::RotationMethod::affine_fit, 0.5);
    write_reduction(files, r);
    return files.read_model("M2", {0.09, 0.006, 0.0}, StiffnessColumn::value, false);
  }
} // namespace

TEST_CASE("a chain with twist axes exports each joint's psi hinge anchored on its twist pivot")
{
  softchain::testing::ScratchDirectory dir("mjcf_twist");
  const ChainModel  model = twist_axis_finger(dir);
  REQUIRE(model.chain().n_joints() == 9);
  const std::string xml = MjcfExport(model, {}).text();
  CHECK(softchain::testing::occurrences(xml, "<body name=") == 9);
  CHECK(softchain::testing::occurrences(xml, "<joint name=") == 27);
  // psi turns about the axis 4 mm above the joint, theta and phi about it.
  CHECK(softchain::testing::occurrences(xml, "_psi\" axis=\"1 0 0\" pos=\"0 0.0040000000000000001 0\"") == 9);
  CHECK(softchain::testing::occurrences(xml, "_theta\" axis=\"0 1 0\" stiffness") == 9);
}

TEST_CASE("the MJCF has three hinges x, y, z per joint with the CSV stiffness and a pressure actuator")
{
  const ChainModel  model = tapered_finger();
  const std::string xml   = MjcfExport(model, {}).text();
  CHECK(softchain::testing::occurrences(xml, "<joint name=") == 27);
  CHECK(softchain::testing::occurrences(xml, "<body name=") == 9);
  const auto psi = xml.find("joint4_psi\" axis=\"1 0 0\""), theta = xml.find("joint4_theta\" axis=\"0 1 0\""),
             phi = xml.find("joint4_phi\" axis=\"0 0 1\"");
  CHECK(psi < theta);
  CHECK(theta < phi);
  CHECK(phi != std::string::npos);
  // Stiffness and damping of joint 4's theta hinge, written with 17 digits:
  // they read back exactly.
  const auto   stiffness = xml.find("stiffness=\"", theta) + 11;
  const double k_theta   = model.stiffness().joint(3)[1];
  CHECK(std::stod(xml.substr(stiffness)) == k_theta);
  CHECK(std::stod(xml.substr(xml.find("damping=\"", theta) + 9)) == 0.01 * k_theta);
  CHECK(softchain::testing::occurrences(xml, "coef=") == 27);
  CHECK(xml.find("<motor name=\"pressure\" tendon=\"pressure\"") != std::string::npos);
  CHECK(xml.find("<site name=\"tip\"") != std::string::npos);
}

namespace
{
  // Plain MuJoCo (the MJCF's own fields) at rest under pressure p and the
  // dead tip force f.
  MujocoRestPose mujoco_rest_pose(const ChainModel &model, const MjcfOptions &options, double p,
                                  const Eigen::Vector3d &f)
  {
    softchain::testing::ScratchDirectory dir("chain_mjcf");
    MjcfExport(model, options).write(dir.file("finger.xml"));
    MujocoQuasiStatic mujoco(dir.file("finger.xml"), MujocoQuasiStatic::Pressure::exported_constants);
    const MujocoRestPose pose = mujoco.rest_pose(p, f);
    INFO("steps to rest: " << pose.steps);
    REQUIRE(pose.angles.size() == 27); // both fingers below have 27 hinges
    return pose;
  }
} // namespace

TEST_CASE("MuJoCo comes to rest in the chain solver's pose")
{
  const ChainModel model = tapered_finger();
  const double     p     = 5e4;
  const Eigen::Vector3d f(0.02, 0.05, 0.03), tip = model.chain().tip();
  ChainEquilibrium      solver(model);
  const Equilibrium     e = solver.solve({p, {{tip, f}}});
  REQUIRE(e.converged);
  REQUIRE(e.angles.cwiseAbs().maxCoeff() > 0.1); // far from linear: ~100 deg of bending
  check_same_pose(mujoco_rest_pose(model, {}, p, f), e, solver.pose());
}

TEST_CASE("With K(p), J_p(p) and links shaped by p, the MJCF at p* is exact at p* and is the frozen chain elsewhere")
{
  const double     p_max = 5e4;
  const ChainModel model = tapered_finger_in_pressure(p_max);
  MjcfOptions      options;
  options.pressure = p_max;
  const Eigen::Vector3d f(0.0, 0.02, 0.02), tip = model.chain().tip();

  ChainEquilibrium  chain(model);
  const Equilibrium at_p_max = chain.solve({p_max, {{tip, f}}});
  REQUIRE(at_p_max.converged);
  check_same_pose(mujoco_rest_pose(model, options, p_max, f), at_p_max, chain.pose());

  // At p*/2 plain MuJoCo is the chain with K(p*) and J_p(p*), not the chain
  // with K(p) and J_p(p); the two differ (k_phi 25 % lower, J_p 16 % lower).
  const ChainModel  frozen = MjcfExport(model, options).exported_model();
  ChainEquilibrium  frozen_chain(frozen);
  const Equilibrium half = frozen_chain.solve({0.5 * p_max, {{tip, f}}});
  REQUIRE(half.converged);
  check_same_pose(mujoco_rest_pose(model, options, 0.5 * p_max, f), half, frozen_chain.pose());
  REQUIRE(chain.solve({0.5 * p_max, {{tip, f}}}).converged);
  CHECK((chain.pose().tip_position - frozen_chain.pose().tip_position).norm() > 1e-3);
}

TEST_CASE("MuJoCo comes to rest in the pose of a chain with twist axes")
{
  softchain::testing::ScratchDirectory dir("mjcf_twist_rest");
  const ChainModel      model = twist_axis_finger(dir);
  const double          p     = 4e4;
  const Eigen::Vector3d f(0.02, 0.05, 0.03), tip = model.chain().tip();
  ChainEquilibrium      solver(model);
  const Equilibrium     e = solver.solve({p, {{tip, f}}});
  REQUIRE(e.converged);
  // MuJoCo's hinge anchors are the chain's pivots: the same pose to the
  // tolerance of check_same_pose.
  check_same_pose(mujoco_rest_pose(model, {}, p, f), e, solver.pose());
  CHECK(e.angles.cwiseAbs().maxCoeff() > 0.1); // far from linear
  CHECK(e.angles[0] != 0.0);                   // the twist pivots are used
}
