// MJCF export: the structure of the file, and (with libmujoco-dev) MuJoCo
// itself: loaded, driven by the same pressure and tip force with gravity off
// and stepped with damping to rest, it must find the chain solver's pose.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/mjcf_export.h>

#include "../data/occurrences.h"
#include "../data/scratch_directory.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>

#ifdef SOFTCHAIN_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using namespace softchain::chain;
namespace data = softchain::data;

namespace
{
  // A tapered finger: joint centres dropping in y, stiffness and J_p varying
  // along it, J_p with all three components so that every hinge is driven.
  ChainModel tapered_finger()
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

#ifdef SOFTCHAIN_HAVE_MUJOCO
namespace
{
  struct RestPose
  {
    Eigen::VectorXd angles;
    Eigen::Vector3d tip;
  };

  // MuJoCo's rest pose of the MJCF of `model` (options `options`) under
  // pressure p and the dead tip force f, gravity off, stepped with damping
  // until the joint speeds are below 1e-11 rad/s. With damping c = k * 0.01 s
  // the unbalanced spring torque left is c |qdot| = 1e-13 k, i.e. an angle
  // error of 1e-13 rad.
  RestPose mujoco_rest_pose(const ChainModel &model, const MjcfOptions &options, double p,
                            const Eigen::Vector3d &f)
  {
    softchain::testing::ScratchDirectory dir("chain_mjcf");
    MjcfExport(model, options).write(dir.file("finger.xml"));
    char     error[1000] = "";
    mjModel *m = mj_loadXML(dir.file("finger.xml").c_str(), nullptr, error, sizeof(error));
    INFO(error);
    REQUIRE(m != nullptr);
    REQUIRE(m->nq == 27); // both fingers below have 27 hinges
    mjData *d = mj_makeData(m);
    m->opt.gravity[2] = 0.0;
    d->ctrl[0]        = p;
    const int last = m->nbody - 1, site = mj_name2id(m, mjOBJ_SITE, "tip");
    // The dead tip force as MuJoCo's applied wrench on the last body (at
    // its centre of mass): force f and torque (tip - com) x f, every step.
    const auto apply_tip_force = [&] {
      const Eigen::Map<const Eigen::Vector3d> at(d->site_xpos + 3 * site), com(d->xipos + 3 * last);
      Eigen::Map<Eigen::Matrix<double, 6, 1>>(d->xfrc_applied + 6 * last) << f, (at - com).cross(f);
    };
    long steps = 0;
    for (mj_forward(m, d); steps < 2000000; ++steps)
      {
        apply_tip_force();
        mj_step(m, d);
        if (Eigen::Map<const Eigen::VectorXd>(d->qvel, m->nv).cwiseAbs().maxCoeff() < 1e-11 && steps > 10)
          break;
      }
    mj_forward(m, d);
    INFO("steps to rest: " << steps);
    const RestPose pose{Eigen::Map<const Eigen::VectorXd>(d->qpos, m->nq),
                        Eigen::Map<const Eigen::Vector3d>(d->site_xpos + 3 * site)};
    mj_deleteData(d);
    mj_deleteModel(m);
    return pose;
  }

  // Tolerance: the chain's Newton tolerance 1e-10 (relative residual) gives
  // angles to ~1e-10 of their size (0.2 rad); MuJoCo's rest criterion adds
  // 1e-13 rad: 1e-10 rad per hinge, and 9 hinges times 0.1 m arm bound the
  // tip position error by 1e-10 m.
  void check_same_pose(const RestPose &mujoco, const Equilibrium &e, const ChainPose &pose)
  {
    CHECK((mujoco.angles - e.angles).cwiseAbs().maxCoeff() < 1e-10);
    CHECK((mujoco.tip - pose.tip_position).norm() < 1e-10);
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
  // The tapered finger with k_phi falling and J_p growing linearly in p,
  // its links stretching by 3 % and sinking by 0.2 mm per joint at p*.
  ChainModel       base  = tapered_finger();
  const double     p_max = 5e4;
  JointStiffness   k     = base.stiffness();
  std::vector<PiecewiseLinear> k_phi, jp;
  for (int i = 0; i < 9; ++i)
    k_phi.emplace_back(std::vector<double>{0, p_max}, std::vector<double>{k.joint(i)[2], 0.6 * k.joint(i)[2]});
  k.set_in_pressure(2, k_phi);
  const Eigen::VectorXd rest = base.actuation().rest_torque_per_pascal();
  for (Eigen::Index j = 0; j < rest.size(); ++j)
    jp.emplace_back(std::vector<double>{0, p_max}, std::vector<double>{rest[j], 1.3 * rest[j]});
  PressureActuation actuation(rest);
  actuation.set_torque_in_pressure(jp);
  ChainModel model("in pressure", base.chain(), k, actuation);
  const auto stretched = [&](const Eigen::Vector3d &X, const double sink) {
    const Eigen::Vector3d at_p_max = 1.03 * X - Eigen::Vector3d(0, sink, 0);
    const auto line = [&](const int c) { return PiecewiseLinear({0, p_max}, {X(c), at_p_max(c)}); };
    return LinkGeometry::PointInPressure{line(0), line(1), line(2)};
  };
  std::vector<LinkGeometry::PointInPressure> joints;
  for (int i = 0; i < 9; ++i)
    joints.push_back(stretched(base.chain().joint_centre(i), 2e-4 * i));
  model.set_link_geometry(LinkGeometry(joints, stretched(base.chain().tip(), 2e-3),
                                       {PiecewiseLinear({0}, {0}), PiecewiseLinear({0}, {0}),
                                        PiecewiseLinear({0}, {0})}));
  MjcfOptions      options;
  options.pressure = p_max;
  const Eigen::Vector3d f(0.0, 0.02, 0.02), tip = model.chain().tip();

  ChainEquilibrium  chain(model);
  const Equilibrium at_p_max = chain.solve({p_max, {{tip, f}}});
  REQUIRE(at_p_max.converged);
  check_same_pose(mujoco_rest_pose(model, options, p_max, f), at_p_max, chain.pose());

  // At p*/2 MuJoCo is the chain with K(p*) and J_p(p*), not the chain with
  // K(p) and J_p(p); the two differ (k_phi 20 % higher, J_p 15 % lower).
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
#endif
