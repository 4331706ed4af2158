// MuJoCo scenes of an exported finger with an obstacle (MujocoScene) under a
// pressure ramp (PressureRampSimulation): the steady contact force is the
// one the chain's equilibrium needs, and unusable input is a clear error.
#include <softchain/chain/mjcf_export.h>
#include <softchain/chain/pressure_ramp_simulation.h>
#include <softchain/chain/simulate_run.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "tapered_finger.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <fstream>

using namespace softchain::chain;
using softchain::data::ObstacleRecord;

namespace
{
  constexpr double p_max = 5e4;

  // The tapered finger bending down (-y), as the FEM's fingers do.
  ChainModel finger_bending_down()
  {
    const ChainModel up = testing::tapered_finger();
    return ChainModel("down", up.chain(), up.stiffness(),
                      PressureActuation(-up.actuation().rest_torque_per_pascal()));
  }

  std::string export_finger(const softchain::testing::ScratchDirectory &dir, const ChainModel &model)
  {
    MjcfExport(model, {0.005, 1070, 0.01, p_max, p_max, {}, 0.0}).write(dir.file("finger.xml"));
    return dir.file("finger.xml");
  }

  // A table 6.5 mm under the joint line: 0.9 mm under the tip's 2 mm capsule at rest.
  ObstacleRecord table()
  {
    ObstacleRecord o;
    o.name      = "table";
    o.shape     = "plane";
    o.position  = {0, -0.0065, 0};
    o.direction = {0, 1, 0};
    return o;
  }
} // namespace

TEST_CASE("MuJoCo's steady contact force on a table is the force the chain's equilibrium needs")
{
  softchain::testing::ScratchDirectory dir("mujoco_scene_table");
  const ChainModel model = finger_bending_down();
  MujocoScene      scene(export_finger(dir, model), table(), 0.002, dir.file("scene.xml"));
  REQUIRE(scene.has_obstacle());
  const double           p = 0.2 * p_max;
  PressureRampSimulation ramp(scene, {20e3, 3.0, 0.25, 0});
  const SteadyContact    steady = ramp.run({p}).front();
  // The table is pushed down, into itself.
  CHECK(steady.force.y() < -0.01);
  CHECK(std::abs(steady.force.x()) < 1e-9 * std::abs(steady.force.y())); // frictionless: along the normal
  // MuJoCo's contacts (the tip link only) as dead loads on the chain at the
  // material points they touch: the chain's equilibrium under them is
  // MuJoCo's pose. Body i's frame is world-aligned at U_i at zero angles
  // (MjcfExport), so a point x of link i is X = U_i + R_i^T (x - x_i).
  const int last = mj_name2id(scene.model(), mjOBJ_BODY, "link9");
  ChainLoad load{p, {}};
  for (const ObstacleContact &c : scene.obstacle_contacts())
    {
      REQUIRE(c.body == last);
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(scene.data()->xmat + 9 * last);
      const Eigen::Map<const Eigen::Vector3d> origin(scene.data()->xpos + 3 * last);
      load.point_loads.push_back({model.chain().link_joint(8) + R.transpose() * (c.position - origin), -c.force});
    }
  REQUIRE_FALSE(load.point_loads.empty());
  const Eigen::VectorXd mujoco = Eigen::Map<const Eigen::VectorXd>(scene.data()->qpos, scene.model()->nq);
  ChainEquilibrium      chain(model);
  const Equilibrium     e = chain.solve(load, mujoco);
  REQUIRE(e.converged);
  // Tolerance: the full contact force moves the chain's angles by 0.05 rad
  // (the free finger's below), a force wrong by 1 % by ~5e-4 rad. MuJoCo
  // after 3 s of hold (300 damping times c / k) is at rest but for its
  // last drift, and the contact points are those of the last step's start:
  // the chain lands 7e-8 rad from MuJoCo's angles. 1e-6 rad is a relative
  // force error of ~2e-5.
  CHECK((e.angles - mujoco).cwiseAbs().maxCoeff() < 1e-6);
  // Without the contact force the chain bends through the table.
  const Equilibrium free = chain.solve({p, {}});
  CHECK((free.angles - mujoco).cwiseAbs().maxCoeff() > 1e-3);
}

TEST_CASE("On a rough table MuJoCo's finger keeps its friction over a slow ramp")
{
  // The same finger pressed on the table with mu = 0.5: the tip slides along
  // the table as it presses, and the table holds it back. MuJoCo's soft
  // contacts creep under a steady tangential load, which the elliptic cone
  // and the no-slip passes (MujocoScene) stop.
  softchain::testing::ScratchDirectory dir("mujoco_scene_rough_table");
  ObstacleRecord rough = table();
  rough.friction       = 0.5;
  MujocoScene scene(export_finger(dir, finger_bending_down()), rough, 0.002, dir.file("scene.xml"));
  CHECK(scene.model()->opt.cone == mjCONE_ELLIPTIC);
  CHECK(scene.model()->opt.noslip_iterations > 0);
  PressureRampSimulation ramp(scene, {20e3, 3.0, 0.25, 0});
  const SteadyContact    steady = ramp.run({0.2 * p_max}).front();
  REQUIRE(steady.force.y() < -0.01);
  const double tangential = std::hypot(steady.force.x(), steady.force.z());
  CHECK(tangential <= 0.5 * std::abs(steady.force.y()) * (1 + 1e-6)); // inside Coulomb's cone
  // Measured T / N = 0.24; with MuJoCo's defaults (pyramidal cone, no
  // no-slip pass) 5e-5: the friction had crept away.
  CHECK(tangential > 0.05 * std::abs(steady.force.y()));
}

TEST_CASE("MuJoCo's skins give as the chain's: each slide joint at rest holds c_s(p) times the force along it")
{
  softchain::testing::ScratchDirectory dir("mujoco_scene_skin");
  ChainModel model = finger_bending_down();
  // c_s from 2 mm/N at rest to 1 mm/N at p*: set from the tables at p.
  model.set_skin_compliance(PiecewiseLinear({0.0, p_max}, {2e-3, 1e-3}));
  MjcfOptions options{0.005, 1070, 0.01, p_max, p_max, {}, 0.0};
  options.skin_links.assign(model.chain().n_joints(), 1);
  options.skin_links[0] = 0; // the first link stays rigid
  MjcfExport(model, options).write(dir.file("finger.xml"));
  MujocoScene scene(dir.file("finger.xml"), table(), 0.002, dir.file("scene.xml"));
  const mjModel *m = scene.model();
  CHECK(mj_name2id(m, mjOBJ_JOINT, "skin1") < 0);
  const double           p = 0.2 * p_max;
  PressureRampSimulation ramp(scene, {20e3, 3.0, 0.25, 0});
  const SteadyContact    steady = ramp.run({p}).front();
  REQUIRE(steady.force.y() < -0.01);
  const int    skin9 = mj_name2id(m, mjOBJ_JOINT, "skin9"), body9 = mj_name2id(m, mjOBJ_BODY, "skin9");
  const double c_s   = 2e-3 + (1e-3 - 2e-3) * p / p_max;
  REQUIRE(skin9 >= 0);
  CHECK(m->jnt_stiffness[skin9] == Approx(1.0 / c_s).epsilon(1e-14));
  // The tip's capsule alone touches; its skin body carries the contact. The
  // slide joint's spring holds the force along the link's +y (the joint's
  // axis in world): s = c_s F . d, at rest but for MuJoCo's last drift:
  // measured 3e-5 relative (the soft contact's force is that of the last
  // step's start, on a capsule held by a spring and damper).
  Eigen::Vector3d on_finger = Eigen::Vector3d::Zero();
  for (const ObstacleContact &c : scene.obstacle_contacts())
    {
      REQUIRE(c.body == body9);
      on_finger -= c.force;
    }
  const Eigen::Map<const Eigen::Vector3d> axis(scene.data()->xaxis + 3 * skin9);
  const double                            s = scene.data()->qpos[m->jnt_qposadr[skin9]];
  CHECK(s > 1e-5); // the palm gives into the finger
  CHECK(s == Approx(c_s * on_finger.dot(axis)).epsilon(1e-4));
}

TEST_CASE("An obstacle MuJoCo cannot build is an error naming the obstacle and its parameter")
{
  softchain::testing::ScratchDirectory dir("mujoco_scene_bad_shape");
  const std::string finger = export_finger(dir, finger_bending_down());
  ObstacleRecord    torus  = table();
  torus.shape              = "torus";
  CHECK_THROWS_AS(MujocoScene(finger, torus, 0.002, dir.file("scene.xml")), softchain::data::InputError);
  CHECK_THROWS_WITH(MujocoScene(finger, torus, 0.002, dir.file("scene.xml")),
                    Catch::Contains("Contact/table") && Catch::Contains("Shape = torus"));
  ObstacleRecord moving = table();
  moving.motion         = {0, 0.001, 0};
  CHECK_THROWS_WITH(MujocoScene(finger, moving, 0.002, dir.file("scene.xml")), Catch::Contains("Motion"));
  ObstacleRecord turning = table();
  turning.motion_rotation = {0, 0, 0.1};
  CHECK_THROWS_WITH(MujocoScene(finger, turning, 0.002, dir.file("scene.xml")),
                    Catch::Contains("Contact/table") && Catch::Contains("Motion rotation"));
  ObstacleRecord meshed = table();
  meshed.shape          = "stl";
  CHECK_THROWS_WITH(MujocoScene(finger, meshed, 0.002, dir.file("scene.xml")),
                    Catch::Contains("Contact/table") && Catch::Contains("Shape = stl") &&
                      Catch::Contains("plane, sphere, cylinder or box"));
  CHECK_THROWS_WITH(MujocoScene(dir.file("none.xml"), table(), 0.002, dir.file("scene.xml")),
                    Catch::Contains("none.xml") && Catch::Contains("--export-mjcf"));
}

TEST_CASE("Every shape of subsection Contact is a MuJoCo primitive in the scene")
{
  softchain::testing::ScratchDirectory dir("mujoco_scene_shapes");
  const std::string finger = export_finger(dir, finger_bending_down());
  ObstacleRecord    o      = table();
  o.radius                 = 0.01;
  o.half_sizes             = {0.01, 0.01, 0.01};
  const std::pair<const char *, int> shapes[] = {
    {"plane", mjGEOM_PLANE}, {"sphere", mjGEOM_SPHERE}, {"cylinder", mjGEOM_CYLINDER}, {"box", mjGEOM_BOX}};
  for (const auto &[shape, type] : shapes)
    {
      o.shape = shape;
      const MujocoScene scene(finger, o, 0.002, dir.file("scene.xml"));
      CHECK(scene.model()->geom_type[mj_name2id(scene.model(), mjOBJ_GEOM, "obstacle")] == type);
    }
  // A turned box keeps its turn: 0.4 rad about (1, 2, 2)/3 is MuJoCo's geom
  // quaternion (cos 0.2, sin 0.2 (1, 2, 2)/3).
  o.shape    = "box";
  o.rotation = {0.4 / 3, 0.8 / 3, 0.8 / 3};
  const MujocoScene turned(finger, o, 0.002, dir.file("scene.xml"));
  const mjtNum     *q = turned.model()->geom_quat + 4 * mj_name2id(turned.model(), mjOBJ_GEOM, "obstacle");
  CHECK(q[0] == Approx(std::cos(0.2)).margin(1e-12));
  for (int i = 0; i < 3; ++i)
    CHECK(q[i + 1] == Approx(std::sin(0.2) * std::vector<double>{1, 2, 2}[i] / 3).margin(1e-12));
}

TEST_CASE("softchain simulate with an unknown scene name is an error naming --scene and the obstacles")
{
  softchain::testing::ScratchDirectory dir("mujoco_scene_unknown");
  std::ofstream(dir.file("f.prm")) << "subsection Contact\n  subsection table\n    set Shape = plane\n"
                                      "    set Position = 0, -0.005, 0\n    set Normal = 0, 1, 0\n  end\nend\n";
  const auto run = [&] {
    run_simulate(softchain::data::PrmFile::read(dir.file("f.prm")), dir.file("database.h5"), dir.path().string(), "wall");
  };
  CHECK_THROWS_AS(run(), softchain::data::InputError);
  CHECK_THROWS_WITH(run(), Catch::Contains("--scene wall") && Catch::Contains("its obstacles: table"));
}
