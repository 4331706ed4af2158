// MuJoCo set to each pressure from the MJCF's pressure tables
// (MujocoPressureActuation) against the chain whose K(p), J_p(p) and link
// geometry U(p) all change with p; and the errors of unusable input.
#include <softchain/chain/mjcf_export.h>
#include <softchain/chain/mujoco_pressure_actuation.h>
#include <softchain/chain/mujoco_tip_distances.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "tapered_finger.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace softchain::chain;
using namespace softchain::chain::testing;

namespace
{
  constexpr double p_max = 5e4;

  // The finger of tapered_finger_in_pressure exported at p* = p_max.
  std::string export_finger(const softchain::testing::ScratchDirectory &dir, const ChainModel &model)
  {
    MjcfOptions options;
    options.pressure     = p_max;
    options.max_pressure = p_max;
    MjcfExport(model, options).write(dir.file("finger.xml"));
    return dir.file("finger.xml");
  }
} // namespace

TEST_CASE("MuJoCo set from the pressure tables rests where the chain does at 5 pressures between 0 and p*")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_rest");
  const ChainModel model = tapered_finger_in_pressure(p_max);
  const std::string path = export_finger(dir, model);
  // Between the tables' pressures (0, 0.4 p*, p*), on the kink and at p*.
  const std::vector<double> pressures{0.1 * p_max, 0.25 * p_max, 0.4 * p_max, 0.7 * p_max, p_max};
  // The finger's length L = 0.09 m bends over 90 degrees at p*: the chain's
  // tip moves by centimetres. Set from the tables, MuJoCo's finger is the
  // chain at every pressure, up to the equilibrium tolerances of
  // check_same_pose: 1e-10 m, far inside the 0.1 % of L (90 um) required of
  // it. Plain MuJoCo (constants of p*) misses by millimetres between 0 and
  // p*: the check tells the two apart.
  for (const MujocoTipDistance &d : mujoco_tip_distances(model, path, pressures))
    {
      INFO("pressure " << d.pressure << " Pa");
      CHECK(d.with_tables < 1e-10);
      CHECK(d.with_tables < 1e-3 * 0.09);
      if (d.pressure < p_max)
        CHECK(d.exported_constants > 1e-3);
    }
}

TEST_CASE("MuJoCo set from the pressure tables finds the chain's angles under pressure and a tip force")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_force");
  const ChainModel      model = tapered_finger_in_pressure(p_max);
  MujocoQuasiStatic     mujoco(export_finger(dir, model), MujocoQuasiStatic::Pressure::tables);
  ChainEquilibrium      solver(model);
  const Eigen::Vector3d f(0.02, 0.05, 0.03), tip = model.chain().tip();
  for (const double p : {0.3 * p_max, 0.6 * p_max})
    {
      INFO("pressure " << p << " Pa");
      const Equilibrium e = solver.solve({p, {{tip, f}}});
      REQUIRE(e.converged);
      CHECK(e.angles.cwiseAbs().maxCoeff() > 0.1); // far from linear
      check_same_pose(mujoco.rest_pose(p, f), e, solver.pose());
    }
}

TEST_CASE("MujocoPressureActuation sets the stiffness, damping, tendon and links of the pressure")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_fields");
  const ChainModel model = tapered_finger_in_pressure(p_max);
  char             error[1000] = "";
  mjModel         *m           = mj_loadXML(export_finger(dir, model).c_str(), nullptr, error, sizeof(error));
  REQUIRE(m != nullptr);
  mjData *d = mj_makeData(m);
  const MujocoPressureActuation actuation(m);
  const double                  p = 0.25 * p_max;
  actuation.apply(p, m, d);
  const Eigen::VectorXd k = model.stiffness().diagonal(p), jp = model.actuation().torque_per_pascal(p);
  const KinematicChain  links = model.chain_at(p);
  const int phi = mj_name2id(m, mjOBJ_JOINT, "joint5_phi"), body = mj_name2id(m, mjOBJ_BODY, "link5");
  CHECK(m->jnt_stiffness[phi] == Approx(k[14]).epsilon(1e-14));
  CHECK(m->dof_damping[m->jnt_dofadr[phi]] == Approx(0.01 * k[14]).epsilon(1e-14));
  CHECK((Eigen::Map<const Eigen::Vector3d>(m->body_pos + 3 * body) - (links.link_joint(4) - links.link_joint(3)))
          .norm() < 1e-15);
  CHECK(d->ctrl[0] == p);
  // The tendon's moment on each hinge is J_p(p): the motor's torque J_p(p) p.
  mj_forward(m, d);
  CHECK((Eigen::Map<const Eigen::VectorXd>(d->qfrc_actuator, m->nv) - jp * p).cwiseAbs().maxCoeff() <
        1e-14 * (jp * p).cwiseAbs().maxCoeff());
  mj_deleteData(d);
  mj_deleteModel(m);
}

TEST_CASE("A pressure outside the tables is an error that names the tables' range and changes nothing")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_range");
  mjModel *m = mj_loadXML(export_finger(dir, tapered_finger_in_pressure(p_max)).c_str(), nullptr, nullptr, 0);
  REQUIRE(m != nullptr);
  mjData                       *d = mj_makeData(m);
  const MujocoPressureActuation actuation(m);
  const double                  k = m->jnt_stiffness[2];
  CHECK_THROWS_WITH(actuation.apply(1.2 * p_max, m, d), Catch::Contains("outside the pressure table") &&
                                                           Catch::Contains("0 to 50000 Pa"));
  CHECK_THROWS_AS(actuation.apply(-1.0, m, d), std::out_of_range);
  CHECK(m->jnt_stiffness[2] == k);
  mj_deleteData(d);
  mj_deleteModel(m);
}

TEST_CASE("An MJCF without the pressure tables is an input error, not a crash")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_no_tables");
  std::ofstream(dir.file("plain.xml"))
    << "<mujoco><worldbody><body name=\"link1\"><joint name=\"joint1_psi\" type=\"hinge\"/>"
       "<geom name=\"link1\" type=\"capsule\" size=\"0.005\" fromto=\"0 0 0 0.01 0 0\"/>"
       "<site name=\"tip\" pos=\"0.01 0 0\"/></body></worldbody></mujoco>\n";
  const auto with_tables = [&] { MujocoQuasiStatic(dir.file("plain.xml"), MujocoQuasiStatic::Pressure::tables); };
  CHECK_THROWS_AS(with_tables(), softchain::data::InputError);
  CHECK_THROWS_WITH(with_tables(), Catch::Contains("no custom numeric field 'softchain_pressure'"));
  // Plain MuJoCo still runs it.
  MujocoQuasiStatic plain(dir.file("plain.xml"), MujocoQuasiStatic::Pressure::exported_constants);
  CHECK(plain.rest_pose(1e4).tip.x() == Approx(0.01));
  CHECK_THROWS_AS(MujocoQuasiStatic(dir.file("missing.xml"), MujocoQuasiStatic::Pressure::tables),
                  softchain::data::InputError);
}

TEST_CASE("Tables whose rows do not match the hinges are an input error naming the field")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_bad_rows");
  std::string xml = MjcfExport(tapered_finger_in_pressure(p_max), {0.005, 1070, 0.01, p_max, p_max, {}, 0.0}).text();
  // One stiffness value too few: not a whole row per pressure.
  const auto at = xml.find("\"", xml.find("data=\"", xml.find(PressureTables::stiffness_name)) + 6);
  xml.erase(xml.rfind(' ', at), at - xml.rfind(' ', at));
  std::ofstream(dir.file("bad.xml")) << xml;
  mjModel *m = mj_loadXML(dir.file("bad.xml").c_str(), nullptr, nullptr, 0);
  REQUIRE(m != nullptr);
  CHECK_THROWS_AS(MujocoPressureActuation(m), softchain::data::InputError);
  CHECK_THROWS_WITH(MujocoPressureActuation(m), Catch::Contains("softchain_stiffness"));
  mj_deleteModel(m);
}

TEST_CASE("A skin joint without its compliance table is an input error naming the joint and the field")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_skin_without_table");
  ChainModel model = tapered_finger_in_pressure(p_max);
  model.set_skin_compliance(PiecewiseLinear({0.0, p_max}, {2e-3, 1e-3}));
  MjcfOptions options{0.005, 1070, 0.01, p_max, p_max, {}, 0.0};
  options.skin_links.assign(model.chain().n_joints(), 1);
  std::string xml = MjcfExport(model, options).text();
  REQUIRE(xml.find("<joint name=\"skin3\" type=\"slide\"") != std::string::npos);
  // The skin's table removed, its joints left.
  const auto line = xml.find("<numeric name=\"" + std::string(PressureTables::skin_compliance_name));
  REQUIRE(line != std::string::npos);
  xml.erase(line, xml.find('\n', line) - line);
  std::ofstream(dir.file("bad.xml")) << xml;
  mjModel *m = mj_loadXML(dir.file("bad.xml").c_str(), nullptr, nullptr, 0);
  REQUIRE(m != nullptr);
  CHECK_THROWS_WITH(MujocoPressureActuation(m),
                    Catch::Contains("skin joint skin1") && Catch::Contains("softchain_skin_compliance"));
  mj_deleteModel(m);
}

TEST_CASE("Two capsules per link sit side by side along the link at every pressure")
{
  softchain::testing::ScratchDirectory dir("mujoco_pressure_two_capsules");
  const ChainModel model = tapered_finger_in_pressure(p_max);
  MjcfOptions      options{0.002, 1070, 0.01, p_max, p_max, {}, 0.0};
  options.capsule_offset = 0.004;
  MjcfExport(model, options).write(dir.file("finger.xml"));
  mjModel *m = mj_loadXML(dir.file("finger.xml").c_str(), nullptr, nullptr, 0);
  REQUIRE(m != nullptr);
  mjData                       *d = mj_makeData(m);
  const MujocoPressureActuation actuation(m);
  const double                  p = 0.6 * p_max;
  actuation.apply(p, m, d);
  const KinematicChain  links = model.chain_at(p);
  const Eigen::Vector3d link  = links.link_joint(4) - links.link_joint(3); // link 4, to joint 5
  const int             a = mj_name2id(m, mjOBJ_GEOM, "link4"), b = mj_name2id(m, mjOBJ_GEOM, "link4_side");
  REQUIRE(b >= 0);
  const Eigen::Vector3d side(0, 0, 0.004);
  CHECK((Eigen::Map<const Eigen::Vector3d>(m->geom_pos + 3 * a) - (0.5 * link - side)).norm() < 1e-15);
  CHECK((Eigen::Map<const Eigen::Vector3d>(m->geom_pos + 3 * b) - (0.5 * link + side)).norm() < 1e-15);
  CHECK(m->geom_size[3 * b + 1] == Approx(0.5 * link.norm()).epsilon(1e-14));
  // Both along the link: the capsule's axis (its z) is the link's direction.
  mj_forward(m, d);
  for (const int g : {a, b})
    {
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->geom_xmat + 9 * g);
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> body(d->xmat + 9 * m->geom_bodyid[g]);
      CHECK((body.transpose() * R.col(2) - link.normalized()).norm() < 1e-12);
    }
  mj_deleteData(d);
  mj_deleteModel(m);
}
