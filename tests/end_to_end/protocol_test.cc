// The validation protocol end to end on the tiny bender: the sweep inflates
// it to the tip angle and moves its tip, the FEM's base torques obey the
// design's mirror symmetry, a prescribed twist is the tip's fitted rotation,
// a rerun solves nothing, `softchain run` writes the torque traces, and the
// listing of the protocol's samples lives as long as the protocol.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/vector_of_point.h>

#include "tiny_design.h"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace softchain;

namespace
{
  const std::string protocol = "subsection Protocol\n"
                               "  set Tip angle = 20\n  set Angle tolerance = 0.5\n"
                               "  set Lateral amplitude = 0.002\n  set Bending amplitude = 0.001\n"
                               "  set Twist amplitude = 5\n  set Steps = 2\nend\n";
} // namespace

TEST_CASE("the validation protocol: inflation to the tip angle, tip motions, torque traces")
{
  const testing::TinyDesign design = testing::pipeline_design("protocol", false, protocol);
  const auto                sweep  = design.run("sweep");
  INFO(sweep.output);
  REQUIRE(sweep.status == 0);
  CHECK(sweep.output.find("protocol: 12 tip motions from sample protocol inflation") !=
        std::string::npos);

  const auto database = data::ActuationDatabase::open(design.database());
  const auto fit      = data::TipPoseFit::of_mesh(database.mesh(), design.database());
  const auto pose     = [&](const data::SampleRecord &r) {
    return fit.fit(data::select_nodes(r.x, database.mesh().tip_nodes));
  };
  std::vector<data::SampleRecord> motions;
  for (const auto &id : database.sample_ids())
    if (const auto r = database.read_sample(id); r.actuation.role == "protocol")
      motions.push_back(r);
  REQUIRE(motions.size() == 12);
  const double p = motions.front().actuation.pressure;

  // The state the motions start from turned the tip by 20 deg within the
  // tolerance the .prm asks for.
  data::SampleRecord inflated;
  for (const auto &id : database.sample_ids())
    if (const auto r = database.read_sample(id);
        r.actuation.role == "protocol inflation" && r.actuation.pressure == p)
      inflated = r;
  REQUIRE(inflated.converged());
  const Eigen::Matrix3d R = pose(inflated).rotation;
  CHECK(std::abs(data::rotation_angle_between(Eigen::Matrix3d::Identity(), R) * 180 / M_PI - 20) <= 0.5);

  for (const auto &m : motions)
    {
      REQUIRE(m.converged());
      const Eigen::Vector3d t = R.transpose() * data::vector_of(m.actuation.tip_motion->translation),
                            theta = R.transpose() * data::vector_of(m.actuation.tip_motion->rotation);
      // A twist turns the tip face by the prescribed rotation (held by
      // constraints: exact up to the fit's round-off).
      if (theta.norm() > 0)
        {
          const Eigen::AngleAxisd turned(pose(m).rotation * R.transpose());
          CHECK((turned.angle() * turned.axis() - data::vector_of(m.actuation.tip_motion->rotation)).norm() <
                1e-9);
        }
      // The bender is symmetric about its mid-plane z = const: the lateral
      // motion -t_z mirrors +t_z, base moments being pseudovectors
      // (T_x, T_y change sign, T_z does not). On the Q2 demo bender the two
      // agree to 3.8e-9 of the moment (to 6e-12 where every load step's
      // Newton update is solved exactly; the stepping stones' inexact solves,
      // NewtonSolver's forcing term, are not mirror-symmetric); Newton's
      // tolerances, 1e-6, bound the difference.
      if (t.z() > 1e-6) // a lateral motion (the others' z is round-off)
        for (const auto &n : motions)
          if (std::abs((R.transpose() * data::vector_of(n.actuation.tip_motion->translation)).z() + t.z()) < 1e-12)
            {
              const Eigen::Vector3d a = data::vector_of(m.base_moment), b = data::vector_of(n.base_moment);
              INFO("lateral " << t.z());
              CHECK(a.norm() > 0);
              CHECK(std::abs(a.x() + b.x()) <= 1e-6 * a.norm());
              CHECK(std::abs(a.y() + b.y()) <= 1e-6 * a.norm());
              CHECK(std::abs(a.z() - b.z()) <= 1e-6 * a.norm());
            }
    }

  // The search is deterministic: a rerun finds every trial in the database.
  const auto again = design.run("sweep");
  INFO(again.output);
  CHECK(again.output.find(" 0 solved, 0 failed") != std::string::npos);

  // The chain tier drives M1, M2 and the baseline through the 25 states of
  // the trace (per kind 0, +, ++, +, 0, -, --, -; a final 0).
  const auto run = design.run("run");
  INFO(run.output);
  CHECK(run.status == 0);
  const auto trace   = data::CsvTable::read(design.output() + "/chain/protocol_torques.csv");
  const auto summary = data::CsvTable::read(design.output() + "/chain/protocol_summary.csv");
  CHECK(trace.n_rows() == 25);
  CHECK(summary.n_rows() % 3 == 0);
  bool baseline = false;
  for (std::size_t r = 0; r < summary.n_rows(); ++r)
    {
      baseline = baseline || summary.text(r, "model") == "baseline";
      CHECK(std::isfinite(summary.number(r, "rms_error_Nm")));
    }
  CHECK(baseline);
  // A point contact (the lateral and bending motions) loads the chain's tip
  // with one force and no couple: the base moment about any point is then
  // r x F, perpendicular to the base force F.
  int point_contacts = 0;
  for (std::size_t r = 0; r < trace.n_rows(); ++r)
    if (trace.text(r, "motion") != "twist" && trace.number(r, "amount") != 0)
      for (const std::string model : {"M2", "baseline"})
        {
          const Eigen::Vector3d F(trace.number(r, model + "_Fx"), trace.number(r, model + "_Fy"),
                                  trace.number(r, model + "_Fz"));
          const Eigen::Vector3d M(trace.number(r, model + "_Tx"), trace.number(r, model + "_Ty"),
                                  trace.number(r, model + "_Tz"));
          CHECK(F.norm() > 0);
          CHECK(std::abs(M.dot(F)) <= 1e-9 * M.norm() * F.norm());
          ++point_contacts;
        }
  CHECK(point_contacts == 2 * 12); // 6 moved states per motion kind, 2 models
  CHECK(run.output.find("tip-motion protocol at") != std::string::npos);
  const auto listing = data::CsvTable::read(design.output() + "/protocol_samples.csv");
  REQUIRE(listing.n_rows() == 13);
  CHECK(listing.text(0, "motion") == "inflation");
  CHECK(listing.text(0, "sample") == inflated.id);
}

TEST_CASE("the protocol gives the same samples on 1 rank and on 2 ranks in 2 sample groups")
{
  // Each group solves whole chains on one rank, so every sample is the same
  // serial solve -- provided each group gets the records its chains start
  // from (the inflated state, solved by one group, starts all six motion chains).
  const std::string samples = "set Pressure sweep = 1e3, 2e3, 3e3\nset Sample groups = 2";
  const std::string springs = "subsection Springs\n  set Generate for bender = true\nend\n";
  const testing::TinyDesign serial("protocol_serial", samples, springs + protocol);
  const testing::TinyDesign parallel("protocol_parallel", samples, springs + protocol);
  REQUIRE(serial.run("sweep").status == 0);
  const auto outcome = parallel.run("sweep", 2);
  INFO(outcome.output);
  REQUIRE(outcome.status == 0);
  CHECK(testing::sample_difference(data::ActuationDatabase::open(serial.database()),
                                   data::ActuationDatabase::open(parallel.database())) == "");
}

TEST_CASE("a run without the protocol removes the earlier protocol's listing, tables and plot")
{
  const testing::TinyDesign design = testing::pipeline_design("protocol_dropped", false, protocol);
  const std::vector<std::string> files{"protocol_samples.csv", "chain/protocol_torques.csv",
                                       "chain/protocol_summary.csv", "chain/protocol_torques.png",
                                       "chain/protocol_torques.gp"};
  REQUIRE(design.run("run").status == 0);
  for (const std::string &file : files)
    CHECK(std::filesystem::exists(design.output() + "/" + file));
  // The same design without subsection Protocol: the report, which reads
  // the chain's protocol tables, must not find the earlier ones.
  design.write(testing::pipeline_samples(), testing::pipeline_settings(false));
  const auto outcome = design.run("run");
  INFO(outcome.output);
  REQUIRE(outcome.status == 0);
  for (const std::string &file : files)
    {
      INFO(file);
      CHECK_FALSE(std::filesystem::exists(design.output() + "/" + file));
    }
}

TEST_CASE("a protocol parameter out of range stops the sweep before any solve, naming it")
{
  const testing::TinyDesign design("protocol_bad", "set Pressure sweep = 1e3",
                                   "subsection Protocol\n  set Tip angle = 20\n  set Steps = 0\nend\n");
  const auto outcome = design.run("sweep");
  INFO(outcome.output);
  CHECK(outcome.status == 1);
  CHECK(outcome.output.find("tiny.prm:") != std::string::npos);
  CHECK(outcome.output.find("parameter 'Steps' in subsection 'Protocol': must lie in [1, 100]") !=
        std::string::npos);
  CHECK_FALSE(std::filesystem::exists(design.database()));
}
