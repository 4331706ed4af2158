// run_chain end to end on a synthetic database in the contract layout whose
// samples were deformed by the M2 chain itself: M2 must reproduce them to
// round-off, M1 (other stiffness) and the beam baseline must not.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/chain_parameters.h>
#include <softchain/chain/chain_run.h>
#include <softchain/chain/chain_validation.h>
#include <softchain/chain/finger_collision_surface.h>
#include <softchain/chain/simulate_run.h>
#include <softchain/data/actuation_database.h>
#include <softchain/data/input_error.h>

#include "../data/occurrences.h"
#include "../data/scratch_directory.h"
#include "../data/stream_redirect.h"
#include "box_mesh.h"
#include "reduction_output.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

using namespace softchain::chain;
using namespace softchain;

namespace
{
  const char *chain_prm = "subsection Finger design\n  set Length = 0.09\nend\n"
                          "subsection Chain\n"
                          "  set Stiffness method = M2\n"
                          "  set Slab half-width = 0.5\n"
                          "  set Stiffness column = value\n"
                          "  set Interpolate k_phi in pressure = true\n"
                          "  set Validation roles = validation, pressure\n"
                          "  set Baseline Young's modulus = 2.6e5\n"
                          "  set Newton tolerance = 1e-10\n"
                          "  set Maximum Newton iterations = 50\n"
                          "end\n";

  data::Actuation actuation(double p, const std::string &role, const Eigen::Vector3d &f)
  {
    data::Actuation a;
    a.pressure = p;
    a.role     = role;
    if (f.norm() > 0)
      a.point_forces.push_back({{0.09, 0.0, 0.0}, {f.x(), f.y(), f.z()}});
    return a;
  }

  // A sample whose nodes follow the chain's rigid links at equilibrium.
  data::SampleRecord chain_sample(const ChainModel &model, const data::MeshRecord &mesh,
                                  const std::string &hash, const data::Actuation &a)
  {
    ChainLoad load{a.pressure, {}};
    for (const auto &f : a.point_forces)
      load.point_loads.push_back({{f.point[0], f.point[1], f.point[2]},
                                  {f.force[0], f.force[1], f.force[2]}});
    ChainEquilibrium solver(model);
    REQUIRE(solver.solve(load).converged);
    data::SampleRecord s;
    s.actuation = a;
    s.id        = data::sample_id(hash, a);
    for (const data::Point3 &p : mesh.X)
      {
        const Eigen::Vector3d X(p[0], p[1], p[2]);
        const Eigen::Vector3d x =
          model.chain().point_position(solver.pose(), model.chain().link_of(X), X);
        s.x.push_back({x.x(), x.y(), x.z()});
      }
    return s;
  }

  void write_database(const std::string &path, const ChainModel &model,
                                const data::MeshRecord &mesh)
  {
    const data::DesignRecord design{"box", "0123456789abcdef", "Q1", "test", chain_prm};
    auto database = data::ActuationDatabase::open_or_create(path, design, mesh);
    for (const auto &a : {actuation(3e4, "pressure", {0, 0, 0}), actuation(6e4, "pressure", {0, 0, 0}),
                          actuation(5e4, "validation", {0.0, 0.05, 0.02}),
                          actuation(0.0, "lateral", {0, 0, 0.1})})
      database.store_sample(chain_sample(model, mesh, design.design_hash, a));
  }
} // namespace

namespace
{
  // The centred box mesh, and M2 (uniform) and M1 (30 % stiffer) stiffness
  // files under <out>/stiffness; returns M2's model.
  ChainModel write_two_reductions(const std::string &out)
  {
    chain::testing::UniformReduction m2, m1;
    m1.k *= 1.3;
    const StiffnessFiles m2_files(out + "/stiffness", data::RotationMethod::affine_fit, 0.5);
    chain::testing::write_reduction(m2_files, m2);
    chain::testing::write_reduction(StiffnessFiles(out + "/stiffness", data::RotationMethod::bounding_box, 0.5), m1);
    return m2_files.read_model("M2", {0.09, 0, 0}, StiffnessColumn::value, true);
  }

  data::MeshRecord centred_box_mesh()
  {
    chain::testing::BoxMeshSpec spec;
    spec.y0 = -0.5 * spec.height; // centred: joints on the x axis
    return chain::testing::box_mesh(spec);
  }
} // namespace

TEST_CASE("run_chain validates M1, M2 and the baseline against a database, writes MJCF")
{
  softchain::testing::ScratchDirectory dir("chain_run");
  const std::string         out = dir.file("out");
  const std::string         prm = dir.file("finger.prm");
  std::ofstream(prm) << chain_prm;
  const data::MeshRecord mesh = centred_box_mesh();
  write_database(dir.file("database.h5"), write_two_reductions(out), mesh);

  REQUIRE(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, true) == 0);
  const data::CsvTable table = data::CsvTable::read(out + "/chain/validation.csv");
  REQUIRE(table.n_rows() == 9); // 3 samples of the validation roles x 3 models
  for (std::size_t r = 0; r < table.n_rows(); ++r)
    {
      const double position = table.number(r, "tip_error_mm");
      const double angle    = table.number(r, "orientation_error_deg");
      CHECK(table.text(r, "chain_status") == "converged");
      if (table.text(r, "model") == "M2")
        {
          // The same equilibrium solved twice: only the round-off of the
          // tip-node centroid and the Kabsch SVD (1e-15 of 0.1 m, of 1 rad).
          CHECK(position < 1e-9);
          CHECK(angle < 1e-9);
        }
      else // 30 % stiffer (M1) or beam theory: visibly different poses
        CHECK(position > 0.1);
    }
  const data::CsvTable summary = data::CsvTable::read(out + "/chain/validation_summary.csv");
  CHECK(summary.n_rows() == 9); // 3 models x (pressure, validation, all)
  // The summary of M1 over all roles against the per-sample rows.
  double largest = 0, sum = 0;
  for (std::size_t r = 0; r < table.n_rows(); ++r)
    if (table.text(r, "model") == "M1")
      {
        largest = std::max(largest, table.number(r, "tip_error_mm"));
        sum += table.number(r, "tip_error_mm");
      }
  for (std::size_t r = 0; r < summary.n_rows(); ++r)
    if (summary.text(r, "model") == "M1" && summary.text(r, "roles") == "all")
      {
        CHECK(summary.number(r, "n_samples") == 3);
        CHECK(summary.number(r, "max_tip_error_mm") == Approx(largest).epsilon(1e-14));
        CHECK(summary.number(r, "mean_tip_error_mm") == Approx(sum / 3).epsilon(1e-14));
      }
  // FEM tip poses: one row per validated sample. A pressure-only sample
  // bends the symmetric chain in the x-y plane, so the bending angle about z
  // is, up to its sign, the total rotation angle (two formulas: atan2 of R
  // and the rotation's trace), and the tip moves to the side it turns to.
  // The angle lies in (-180, 180] deg.
  const data::CsvTable tips = data::CsvTable::read(out + "/chain/fem_tip_poses.csv");
  REQUIRE(tips.n_rows() == 3);
  for (std::size_t r = 0; r < tips.n_rows(); ++r)
    if (tips.text(r, "role") == "pressure")
      {
        const double bending = tips.number(r, "tip_bending_angle_deg");
        CHECK(std::abs(bending) > 1.0);
        CHECK(std::abs(bending) == Approx(tips.number(r, "tip_rotation_angle_deg")).epsilon(1e-9));
        if (tips.number(r, "pressure") == 3e4) // 86 deg; 60 kPa curls to 220 deg, wrapped to -140
          CHECK(bending * tips.number(r, "tip_y_mm") > 0);
      }
  // chain_poses.csv: per validated sample and model the n joints and the
  // tip; the tip row is validation.csv's chain tip (mm there, m here).
  const data::CsvTable poses = data::CsvTable::read(out + "/chain/chain_poses.csv");
  REQUIRE(poses.n_rows() == table.n_rows() * 10); // 9 joints + tip
  for (std::size_t r = 0; r < table.n_rows(); ++r)
    {
      const std::size_t tip = 10 * r + 9;
      CHECK(poses.text(tip, "point") == "tip");
      CHECK(poses.text(tip, "sample") == table.text(r, "sample"));
      CHECK(1e3 * poses.number(tip, "x") == Approx(table.number(r, "chain_tip_x_mm")).epsilon(1e-12));
      CHECK(poses.text(tip - 9, "point") == "1");
    }
  std::ifstream     xml(out + "/chain/finger.xml");
  const std::string text((std::istreambuf_iterator<char>(xml)), {});
  CHECK(text.find("joint9_phi") != std::string::npos);
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
    CHECK(std::filesystem::exists(out + "/chain/validation.png"));

  // validation.csv also carries the chain's own tip pose: for M2 (the model
  // the database was written from) it is the FEM tip pose of the same sample,
  // up to the round-off above (1e-9 mm, 1e-9 deg); every solve took time.
  for (std::size_t r = 0; r < table.n_rows(); ++r)
    {
      CHECK(table.number(r, "solve_time_us") > 0.0);
      if (table.text(r, "model") != "M2")
        continue;
      for (std::size_t t = 0; t < tips.n_rows(); ++t)
        if (tips.text(t, "sample") == table.text(r, "sample"))
          {
            for (const std::string axis : {"x", "y", "z"})
              CHECK(table.number(r, "chain_tip_" + axis + "_mm") ==
                    Approx(tips.number(t, "tip_" + axis + "_mm")).margin(1e-9));
            CHECK(table.number(r, "chain_tip_rotation_angle_deg") ==
                  Approx(tips.number(t, "tip_rotation_angle_deg")).margin(1e-9));
          }
    }
}

namespace
{
  data::ObstacleRecord obstacle(const std::string &name, const std::string &shape, const data::Point3 &at,
                                const data::Point3 &direction, double radius)
  {
    data::ObstacleRecord o;
    o.name      = name;
    o.shape     = shape;
    o.position  = at;
    o.direction = direction;
    o.radius    = radius;
    return o;
  }

  // A contact sample made by `model` itself: its surface (the mesh's outer
  // surface on rigid links, as run_chain subdivides it) pressed on `o`
  // (along its load path where `o` has friction), the nodes where its links
  // carry them, the obstacle's wrench what the chain's contact gives it.
  data::SampleRecord chain_contact_sample(ChainModel model, const data::MeshRecord &mesh,
                                          const std::string &hash, double p, const data::ObstacleRecord &o)
  {
    model.set_collision_surface(rigid_collision_surface(model, mesh, ChainParameters().surface_subdivisions));
    data::Actuation a;
    a.pressure  = p;
    a.role      = "contact";
    a.obstacles = {o};
    ChainEquilibrium   solver(model);
    FrictionalLoadPath path(solver); // a single solve without friction
    const Equilibrium  e = path.solve(ChainLoad{p, {}, a.obstacles});
    REQUIRE(e.converged);
    REQUIRE(!solver.contact().touches().empty());
    data::SampleRecord s = chain_sample(model, mesh, hash, actuation(p, "pressure", {0, 0, 0}));
    s.actuation          = a;
    s.id                 = data::sample_id(hash, a);
    for (std::size_t k = 0; k < mesh.X.size(); ++k) // the nodes at the contact pose
      {
        const Eigen::Vector3d X(mesh.X[k][0], mesh.X[k][1], mesh.X[k][2]);
        const Eigen::Vector3d x = model.chain().point_position(solver.pose(), model.chain().link_of(X), X);
        s.x[k]                  = {x.x(), x.y(), x.z()};
      }
    s.obstacle_wrenches = solver.contact().obstacle_wrenches();
    return s;
  }
} // namespace

TEST_CASE("run_chain compares contact samples in force and pose and writes grasp_summary.csv")
{
  softchain::testing::ScratchDirectory dir("chain_run_contact");
  const std::string         out = dir.file("out");
  const std::string         prm = dir.file("finger.prm");
  std::string               text = chain_prm;
  text.replace(text.find("validation, pressure"), 20, "validation, pressure, contact");
  std::ofstream(prm) << text;
  const data::MeshRecord mesh     = centred_box_mesh();
  const ChainModel       m2_model = write_two_reductions(out);
  write_database(dir.file("database.h5"), m2_model, mesh);
  {
    const data::DesignRecord design{"box", "0123456789abcdef", "Q1", "test", chain_prm};
    auto database = data::ActuationDatabase::open_or_create(dir.file("database.h5"), design, mesh);
    // The finger curls towards +y: a table 24 mm above its axis, a 8 mm
    // cylinder 6 mm above its upper side.
    database.store_sample(chain_contact_sample(m2_model, mesh, design.design_hash, 4e4,
                                               obstacle("table", "plane", {0, 0.024, 0}, {0, -1, 0}, 0)));
    database.store_sample(chain_contact_sample(m2_model, mesh, design.design_hash, 3e4,
                                               obstacle("rod", "cylinder", {0.05, 0.02, 0}, {0, 0, 1}, 0.008)));
    auto rough     = obstacle("rough_rod", "cylinder", {0.05, 0.02, 0}, {0, 0, 1}, 0.008);
    rough.friction = 0.5;
    database.store_sample(chain_contact_sample(m2_model, mesh, design.design_hash, 3e4, rough));
  }
  std::ostringstream printed;
  {
    const softchain::testing::StreamRedirect capture(std::cout, printed);
    REQUIRE(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, false) == 0);
  }
  const data::CsvTable table = data::CsvTable::read(out + "/chain/validation.csv");
  int contact_rows = 0;
  for (std::size_t r = 0; r < table.n_rows(); ++r)
    {
      const std::string role = table.text(r, "role");
      if (role != "blocked force" && role != "grasp" && role != "grasp with friction")
        {
          CHECK(std::isnan(table.number(r, "contact_force_N")));
          continue;
        }
      ++contact_rows;
      CHECK(table.text(r, "chain_status") == "converged");
      CHECK(table.number(r, "fem_contact_force_N") > 0.01);
      if (table.text(r, "model") == "M2")
        {
          // Its own contact equilibrium again, from the same start: the
          // solver's tolerance, 1e-10 of the forces.
          CHECK(std::abs(table.number(r, "contact_force_error_percent")) < 1e-6);
          CHECK(table.number(r, "tip_error_mm") < 1e-6);
        }
      else // 30 % stiffer joints press 30 % harder or less deep, beam theory differs
        CHECK(std::abs(table.number(r, "contact_force_error_percent")) > 1.0);
    }
  CHECK(contact_rows == 9); // 3 contact samples x 3 models
  const data::CsvTable summary = data::CsvTable::read(out + "/chain/grasp_summary.csv");
  REQUIRE(summary.n_rows() == 3);
  for (std::size_t r = 0; r < summary.n_rows(); ++r)
    {
      CHECK(summary.number(r, "n_samples") == 3);
      CHECK(summary.number(r, "median_solve_time_us") > 0);
      if (summary.text(r, "model") == "M2")
        {
          CHECK(summary.number(r, "blocked_force_error_percent") < 1e-6);
          CHECK(summary.number(r, "grasp_force_error_percent") < 1e-6);
          CHECK(summary.number(r, "tip_error_percent_L") < 1e-6);
        }
    }
  CHECK(printed.str().find("chain: M2 in contact: blocked force error") != std::string::npos);
  // A kind of contact sample the database lacks is said, not printed as nan.
  CHECK(error_percent(4.8814) == "4.88 %");
  CHECK(error_percent(std::nan("")) == "none (no such sample)");

  // A .prm that no longer asks for the contact samples (the sweep's plan
  // without them): no contact summary, and the last one does not stay behind
  // for the report to show.
  {
    auto                     database = data::ActuationDatabase::open(dir.file("database.h5"));
    std::vector<std::string> free;
    for (const std::string &id : database.sample_ids())
      if (database.read_sample(id).actuation.obstacles.empty())
        free.push_back(id);
    REQUIRE(free.size() + 3 == database.sample_ids().size());
    database.set_plan(free);
  }
  std::ostringstream again;
  {
    const softchain::testing::StreamRedirect capture(std::cout, again);
    REQUIRE(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, false) == 0);
  }
  CHECK_FALSE(std::filesystem::exists(out + "/chain/grasp_summary.csv"));
  CHECK(again.str().find("in contact") == std::string::npos);
  // Nor does an earlier MuJoCo comparison with the FEM's contact samples.
  std::filesystem::create_directories(out + "/simulate");
  std::ofstream(out + "/simulate/contact_vs_fem.csv") << "obstacle,pressure\ntable,40000\n";
  CHECK(simulate_contact_scenes(data::PrmFile::read(prm), dir.file("database.h5"), out) == 0);
  CHECK_FALSE(std::filesystem::exists(out + "/simulate/contact_vs_fem.csv"));
}

TEST_CASE("the Chain subsection is read and checked")
{
  softchain::testing::ScratchDirectory dir("chain_parameters");
  const std::string         prm = dir.file("finger.prm");
  SECTION("values")
  {
    std::ofstream(prm) << chain_prm;
    const ChainParameters p = ChainParameters::read(data::PrmFile::read(prm));
    CHECK(p.method == data::RotationMethod::affine_fit);
    CHECK(p.validation_roles == std::vector<std::string>{"validation", "pressure"});
    CHECK(p.newton.max_iterations == 50);
    CHECK(p.pressure_link_geometry); // the default: links as the pressure shapes them
  }
  SECTION("rigid links, and a link geometry that is neither")
  {
    std::ofstream(prm) << "subsection Chain\n  set Link geometry = rigid\nend\n";
    CHECK_FALSE(ChainParameters::read(data::PrmFile::read(prm)).pressure_link_geometry);
    std::ofstream(prm) << "subsection Chain\n  set Link geometry = bent\nend\n";
    CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                      Catch::Contains(prm + ":2") && Catch::Contains("Link geometry") && Catch::Contains("bent"));
  }
  SECTION("timed solves: how often each sample's solve is timed, at least once")
  {
    std::ofstream(prm) << chain_prm;
    CHECK(ChainParameters::read(data::PrmFile::read(prm)).timed_solves == 1);
    std::ofstream(prm) << "subsection Chain\n  set Timed solves = 5\nend\n";
    CHECK(ChainParameters::read(data::PrmFile::read(prm)).timed_solves == 5);
    std::ofstream(prm) << "subsection Chain\n  set Timed solves = 0\nend\n";
    CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                      Catch::Contains(prm) && Catch::Contains("Timed solves") && Catch::Contains("[1, 1000]"));
  }
  SECTION("counts mistyped by orders of magnitude are errors, not hours of solves")
  {
    // 2^32 + 5 would wrap to 5 in an int.
    for (const std::string entry : {"Surface subdivisions = 300", "Timed solves = 4294967301",
                                    "Friction load steps = 20000", "Maximum Newton iterations = 1e9"})
      {
        INFO(entry);
        std::ofstream(prm) << "subsection Chain\n  set " + entry + "\nend\n";
        CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                          Catch::Contains(prm + ":2") && Catch::Contains(entry.substr(0, entry.find(" ="))));
      }
  }
  SECTION("the sections' compliances: measured (the tables), none, a value, or an error")
  {
    std::ofstream(prm) << chain_prm;
    const ChainParameters measured = ChainParameters::read(data::PrmFile::read(prm));
    CHECK_FALSE(measured.skin_compliance);
    CHECK_FALSE(measured.skin_shear_compliance);
    std::ofstream(prm) << "subsection Chain\n  set Skin compliance = 2e-3\n  set Skin shear compliance = none\nend\n";
    const ChainParameters set = ChainParameters::read(data::PrmFile::read(prm));
    CHECK(set.skin_compliance == 2e-3);
    CHECK(set.skin_shear_compliance == 0.0);
    std::ofstream(prm) << "subsection Chain\n  set Skin shear compliance = -1e-4\nend\n";
    CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                      Catch::Contains(prm) && Catch::Contains("Skin shear compliance") &&
                        Catch::Contains("measured, none or a compliance >= 0"));
  }
  SECTION("a bad method names file, line and parameter")
  {
    std::ofstream(prm) << "subsection Chain\n  set Stiffness method = M3\nend\n";
    CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                      Catch::Contains(prm + ":2") && Catch::Contains("Stiffness method") &&
                        Catch::Contains("M3"));
  }
  SECTION("the stiffness column: value, fit, or an error naming the parameter")
  {
    std::ofstream(prm) << "subsection Chain\n  set Stiffness column = fit\nend\n";
    CHECK(ChainParameters::read(data::PrmFile::read(prm)).stiffness_column == StiffnessColumn::fit);
    std::ofstream(prm) << "subsection Chain\n  set Stiffness column = median\nend\n";
    CHECK_THROWS_WITH(ChainParameters::read(data::PrmFile::read(prm)),
                      Catch::Contains(prm + ":2") && Catch::Contains("Stiffness column") &&
                        Catch::Contains("'median' is not one of: value, fit"));
  }
  SECTION("a missing stiffness file of the selected method")
  {
    std::ofstream(prm) << chain_prm;
    const data::DesignRecord design{"box", "0123456789abcdef", "Q1", "test", chain_prm};
    data::ActuationDatabase::open_or_create(dir.file("db.h5"), design, chain::testing::box_mesh({}));
    CHECK_THROWS_AS(run_chain(data::PrmFile::read(prm), dir.file("db.h5"), dir.file("out"), false), data::InputError);
  }
}

TEST_CASE("the MJCF that run_chain exports keeps a twist-axis chain's twist pivots")
{
  // One body per joint, its psi hinge anchored on the twist pivot 4 mm above
  // the joint (MjcfExport).
  softchain::testing::ScratchDirectory dir("chain_run_twist_mjcf");
  const std::string                    out = dir.file("out");
  const std::string                    prm = dir.file("finger.prm");
  std::ofstream(prm) << chain_prm;
  chain::testing::BoxMeshSpec spec;
  spec.y0 = -0.5 * spec.height;
  const data::MeshRecord           mesh = chain::testing::box_mesh(spec);
  chain::testing::UniformReduction r;
  r.twist_height = 0.004;
  const StiffnessFiles files(out + "/stiffness", data::RotationMethod::affine_fit, 0.5);
  chain::testing::write_reduction(files, r);
  write_database(dir.file("database.h5"), files.read_model("M2", {0.09, 0, 0}, StiffnessColumn::value, true), mesh);
  std::ostringstream printed;
  {
    const softchain::testing::StreamRedirect to(std::cout, printed);
    REQUIRE(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, true) == 0);
  }
  std::ifstream     xml(out + "/chain/finger.xml");
  const std::string text((std::istreambuf_iterator<char>(xml)), {});
  CHECK(softchain::testing::occurrences(text, "<body name=\"link") == 9);
  CHECK(softchain::testing::occurrences(text, "<joint name=") == 27);
  CHECK(softchain::testing::occurrences(text, "_psi\" axis=\"1 0 0\" pos=\"0 0.0040000000000000001 0\"") == 9);
  // The last line: MuJoCo set from the pressure tables against the chain at
  // 11 pressures up to p*. At rest to 1e-12 rad per hinge (MujocoQuasiStatic)
  // its tip is the chain's to ~1e-12 m, 1e-9 % of L = 0.09 m.
  const std::string lines = printed.str(), last = lines.substr(lines.rfind('\n', lines.size() - 2) + 1);
  const std::string head  = "mujoco vs chain over pressure: max tip distance ";
  INFO(lines);
  REQUIRE(last.rfind(head, 0) == 0);
  CHECK(last.substr(last.size() - 7) == "% of L\n");
  CHECK(std::stod(last.substr(head.size())) < 1e-8);
}

TEST_CASE("run_chain with links that shift needs the reduction's shift table, naming it when missing")
{
  softchain::testing::ScratchDirectory dir("chain_run_link_shift");
  const std::string                    out = dir.file("out");
  const std::string                    prm = dir.file("finger.prm");
  std::string                          text = chain_prm;
  text.insert(text.find("end\n", text.find("subsection Chain")), "  set Link shift = measured\n");
  std::ofstream(prm) << text;
  write_database(dir.file("database.h5"), write_two_reductions(out), centred_box_mesh());
  const StiffnessFiles m2(out + "/stiffness", data::RotationMethod::affine_fit, 0.5);
  std::filesystem::remove(m2.link_shift_path());
  CHECK_THROWS_WITH(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, false),
                    Catch::Contains(m2.link_shift_path() + " is missing") && Catch::Contains("Link shift = none"));
  // With the table (here without rows: no in-plane samples) the chain runs, its links unshifted.
  std::ofstream(m2.link_shift_path()) << "pressure,link,shift_x,shift_y,turn_rms,samples\n";
  CHECK(run_chain(data::PrmFile::read(prm), dir.file("database.h5"), out, false) == 0);
}
