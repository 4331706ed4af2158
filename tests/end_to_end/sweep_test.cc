// `softchain sweep` on a tiny bender: database layout, cache, design changes,
// crash safety, failed samples, bad points, 1 vs 2 MPI ranks.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>

#include "../data/occurrences.h"
#include "tiny_design.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

using softchain::data::CsvTable;
using softchain::data::ActuationDatabase;
using softchain::data::Point3;
using softchain::testing::TinyDesign;

namespace
{
  // Small loads: each solve is a few Newton iterations on 112 nodes.
  // Listed out of order: the sweep orders each chain by increasing load.
  const std::string samples = "set Pressure sweep = 2e3, 1e3\n"
                              "set Lateral tip forces = 0.01, 0.02\n"
                              "set Torsion couples = 0.01\n"
                              "set Validation samples = 1.5e3 : tip : 0,0,0.01";

  // The tiny bender's cavity: x in [0.002, 0.078], y in [0.002, 0.010],
  // z in [0.002, 0.016].
  const Point3 cavity_low{0.002, 0.002, 0.002}, cavity_high{0.078, 0.010, 0.016};

  Point3 minus(const Point3 &a, const Point3 &b)
  {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }

  Point3 cross(const Point3 &a, const Point3 &b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  double dot(const Point3 &a, const Point3 &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // The cavity triangles tile the cavity's walls (area 2(ab + bc + ca)) and
  // each points into the cavity (towards its centre: the cavity is convex).
  void check_cavity_triangles(const softchain::data::MeshRecord &mesh)
  {
    const Point3 size = minus(cavity_high, cavity_low);
    const Point3 centre{0.04, 0.006, 0.009};
    double       area = 0.0;
    for (const auto &t : mesh.cavity_triangles)
      {
        const Point3 n =
          cross(minus(mesh.X[t[1]], mesh.X[t[0]]), minus(mesh.X[t[2]], mesh.X[t[0]]));
        area += 0.5 * std::sqrt(dot(n, n));
        CHECK(dot(n, minus(centre, mesh.X[t[0]])) > 0);
      }
    // Only rounding of sums of mm-sized coordinates: 1e-12 relative.
    CHECK(area ==
          Approx(2 * (size[0] * size[1] + size[1] * size[2] + size[2] * size[0])).epsilon(1e-12));
  }

  // The largest coordinate difference of any node of any sample of a and b.
  // The largest nodal position difference of each sample of a and b over
  // the norm |u| of all of the sample's displacements in a (Newton's
  // displacement test's scale), the largest over the samples.
  double relative_position_difference(const ActuationDatabase &a, const ActuationDatabase &b)
  {
    const auto &X       = a.mesh().X;
    double      largest = 0.0;
    for (const auto &id : a.sample_ids())
      {
        const auto x = a.read_sample(id).x, y = b.read_sample(id).x;
        double     difference = 0.0, u_squared = 0.0;
        for (std::size_t n = 0; n < x.size(); ++n)
          for (int c = 0; c < 3; ++c)
            {
              difference = std::max(difference, std::abs(x[n][c] - y[n][c]));
              u_squared += std::pow(x[n][c] - X[n][c], 2);
            }
        largest = std::max(largest, difference / std::max(std::sqrt(u_squared), 1e-300));
      }
    return largest;
  }

  // `serial` swept on one rank and `parallel` on two, both successfully.
  void sweep_on_one_and_two_ranks(const TinyDesign &serial, const TinyDesign &parallel)
  {
    REQUIRE(serial.run("sweep").status == 0);
    const auto outcome = parallel.run("sweep", 2);
    INFO(outcome.output);
    REQUIRE(outcome.status == 0);
  }

  std::string file_bytes(const std::string &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }
} // namespace

TEST_CASE("sweep writes a database whose layout the data layer reads back")
{
  TinyDesign design("sweep_layout", samples, "subsection Output\n  set Write VTU = true\nend\n");
  const auto outcome = design.run("sweep");
  INFO(outcome.output);
  REQUIRE(outcome.status == 0);
  CHECK(outcome.output.find("[6/6]") != std::string::npos);
  CHECK(softchain::testing::occurrences(outcome.output, "ETA") == 6);
  CHECK(outcome.output.find("pressure 1000 Pa") < outcome.output.find("pressure 2000 Pa"));

  const auto  database = ActuationDatabase::open(design.database());
  const auto &mesh     = database.mesh();
  // Q1 on 6 x 3 x 3 cells less the 4 cavity cells: 7*4*4 vertices, 50 cells.
  REQUIRE(mesh.X.size() == 112);
  CHECK(mesh.nodes_per_cell == 8);
  CHECK(mesh.cells.size() == 50 * 8);
  CHECK(mesh.tip_nodes.size() == 16);
  CHECK(mesh.base_nodes.size() == 16);
  for (const auto n : mesh.tip_nodes)
    CHECK(mesh.X[n][0] == Approx(0.08).epsilon(1e-12));
  for (const auto n : mesh.base_nodes)
    CHECK(mesh.X[n][0] == 0.0);

  check_cavity_triangles(mesh);

  REQUIRE(database.sample_ids().size() == 6);
  for (const auto &id : database.sample_ids())
    {
      const auto s = database.read_sample(id);
      CHECK(s.converged());
      CHECK(s.load_factor_reached == 1.0);
      CHECK(s.force_points_deformed.size() == s.actuation.point_forces.size());
      for (const auto n : mesh.base_nodes) // clamped
        CHECK(s.x[n] == mesh.X[n]);
      if (s.actuation.role == "lateral") // a +z force moves its point along +z
        {
          // The default force point: the centre of the tip face.
          const Point3 tip_centre{0.08, 0.006, 0.009};
          for (int c = 0; c < 3; ++c) // midpoints of mesh vertices: rounding only
            CHECK(s.actuation.point_forces[0].point[c] == Approx(tip_centre[c]).epsilon(1e-12));
          CHECK(s.force_points_deformed[0][2] > s.actuation.point_forces[0].point[2]);
        }
      if (s.actuation.role == "torsion") // default arm: a quarter of the 18 mm width
        {
          CHECK(s.actuation.point_forces[0].point[2] == Approx(0.009 + 0.0045));
          CHECK(s.actuation.point_forces[1].point[2] == Approx(0.009 - 0.0045));
        }
      if (s.actuation.role == "torsion") // the couple's points move apart along y
        CHECK(s.force_points_deformed[0][1] - s.actuation.point_forces[0].point[1] ==
              Approx(s.actuation.point_forces[1].point[1] - s.force_points_deformed[1][1]));
      // The base carries the applied forces (the closed cavity's pressure has
      // no resultant). Newton stops at |R| <= 1e-6 |f_ext|; over the ~300
      // free DoFs that leaves ~1e-5 of the load, within the bound 1e-3.
      Point3 applied{0, 0, 0};
      for (const auto &f : s.actuation.point_forces)
        for (int c = 0; c < 3; ++c)
          applied[c] += f.force[c];
      const double load = std::hypot(applied[0], applied[1], applied[2]);
      for (int c = 0; c < 3; ++c)
        {
          CHECK(std::isfinite(s.base_moment[c]));
          CHECK(std::abs(s.base_force[c] - applied[c]) <= 1e-3 * load + 1e-9);
        }
    }
  const std::string series = file_bytes(design.output() + "/vtu/samples.pvd");
  CHECK(softchain::testing::occurrences(series, "<DataSet") == 6);
}

TEST_CASE("the VTU series lists the samples the .prm asks for now, also after a rerun that solves nothing")
{
  const std::string vtu = "subsection Output\n  set Write VTU = true\nend\n";
  TinyDesign        design("sweep_series", samples, vtu);
  REQUIRE(design.run("sweep").status == 0);
  const auto listed = [&] { return softchain::testing::occurrences(file_bytes(design.output() + "/vtu/samples.pvd"), "<DataSet"); };
  CHECK(listed() == 6);
  // The held-out sample leaves the .prm: it stays cached, and leaves the series.
  design.write(samples.substr(0, samples.find("set Validation samples")), vtu);
  const auto rerun = design.run("sweep");
  INFO(rerun.output);
  CHECK(rerun.output.find("5 cached, 0 solved") != std::string::npos);
  CHECK(listed() == 5);
}

TEST_CASE("Q2 and P2 databases hold the mid-side nodes and the sub-triangles of curved faces")
{
  for (const std::string element : {"Q2", "P2"})
    {
      INFO(element);
      TinyDesign design("sweep_" + element, "set Pressure sweep = 1e3",
                        "subsection Mesh\n  set Element type = " + element + "\nend\n");
      const auto outcome = design.run("sweep");
      INFO(outcome.output);
      REQUIRE(outcome.status == 0);
      const auto  database = ActuationDatabase::open(design.database());
      const auto &mesh     = database.mesh();
      check_cavity_triangles(mesh);
      CHECK(mesh.nodes_per_cell == (element == "Q2" ? 8 : 4));
      if (element == "Q2") // 13 x 7 x 7 nodes less the 7 inside the cavity;
        {                   // tip face: 4 x 4 vertices, edge and face midpoints
          CHECK(mesh.X.size() == 630);
          CHECK(mesh.tip_nodes.size() == 49);
        }
      for (const auto n : mesh.tip_nodes)
        CHECK(mesh.X[n][0] == Approx(0.08).epsilon(1e-12));
    }
}

TEST_CASE("a rerun is all cache hits and rewrites nothing, only a design change invalidates")
{
  TinyDesign design("sweep_cache", samples);
  REQUIRE(design.run("sweep").status == 0);
  const std::string before = file_bytes(design.database());
  const auto        time   = std::filesystem::last_write_time(design.database());

  const auto rerun = design.run("sweep");
  INFO(rerun.output);
  CHECK(rerun.status == 0);
  CHECK(rerun.output.find("6 cached, 0 solved") != std::string::npos);
  CHECK(file_bytes(design.database()) == before);
  CHECK(std::filesystem::last_write_time(design.database()) == time);

  // The design hash is taken from the parsed values, not the text: numbers
  // written differently, a default set explicitly and comments keep the cache.
  design.write(samples, "# the same design, written differently\n"
                        "subsection Materials\n  set Density = 1070.0\n  subsection silicone\n"
                        "    set Young's modulus = 260000 # Pa\n"
                        "    set Poisson's ratio = 4.8e-1\n  end\nend\n"
                        "subsection Mesh\n  set Bender cells along length = 04\nend\n");
  const auto reformatted = design.run("sweep");
  INFO(reformatted.output);
  CHECK(reformatted.output.find("6 cached, 0 solved") != std::string::npos);
  CHECK(file_bytes(design.database()) == before);

  // Loads are not part of the design: still all cached.
  design.write(samples, "subsection Loads\n  set Pressure = 5e3\nend\n");
  CHECK(design.run("sweep").output.find("6 cached, 0 solved") != std::string::npos);

  // A stiffer material is another design: everything is solved again and
  // the old database is moved aside.
  const std::string old_hash = ActuationDatabase::open(design.database()).design().design_hash;
  design.write(samples, "subsection Materials\n  subsection silicone\n"
                        "    set Young's modulus = 3e5\n  end\nend\n");
  const auto changed = design.run("sweep");
  INFO(changed.output);
  CHECK(changed.output.find("0 cached, 6 solved") != std::string::npos);
  CHECK(ActuationDatabase::open(design.database()).design().design_hash != old_hash);
  CHECK(std::filesystem::exists(design.database() + "." + old_hash + ".stale"));
}

TEST_CASE("a sweep killed with SIGKILL resumes without recomputing and ends as an uninterrupted run")
{
  const std::string chains = "set Pressure sweep = 1e3, 2e3, 3e3, 4e3\n"
                             "set Lateral tip forces = 0.01, 0.02";
  TinyDesign uninterrupted("sweep_whole", chains);
  REQUIRE(uninterrupted.run("sweep").status == 0);

  TinyDesign  crashed("sweep_crash", chains);
  const auto  partial = crashed.sweep_killed_after(2);
  INFO(partial);
  const auto  stored  = ActuationDatabase::open(crashed.database());
  const auto  ids     = stored.sample_ids();
  REQUIRE(ids.size() >= 2);
  REQUIRE(ids.size() < 6); // killed in the middle
  std::vector<softchain::data::SampleRecord> kept;
  for (const auto &id : ids)
    kept.push_back(stored.read_sample(id)); // intact: every dataset reads back

  const auto resumed = crashed.run("sweep");
  INFO(resumed.output);
  CHECK(resumed.status == 0);
  CHECK(resumed.output.find(std::to_string(ids.size()) + " cached") != std::string::npos);
  const auto final_database = ActuationDatabase::open(crashed.database());
  for (const auto &k : kept) // not recomputed: even the wall time is the stored one
    CHECK(final_database.read_sample(k.id).wall_time == k.wall_time);
  CHECK(softchain::testing::sample_difference(
          final_database, ActuationDatabase::open(uninterrupted.database())) == "");
}

TEST_CASE("Ctrl-C (SIGINT) stops a sweep with status 130, the database intact, a rerun resumes")
{
  TinyDesign  design("sweep_interrupt", "set Pressure sweep = 1e3, 2e3, 3e3, 4e3");
  int         status  = 0;
  const auto  partial = design.sweep_killed_after(1, SIGINT, &status);
  INFO(partial);
  CHECK(status == 130);
  const auto stored = ActuationDatabase::open(design.database());
  const auto ids    = stored.sample_ids();
  REQUIRE(!ids.empty());
  for (const auto &id : ids)
    CHECK(stored.read_sample(id).converged()); // only whole samples were stored
  const auto resumed = design.run("sweep");
  INFO(resumed.output);
  CHECK(resumed.status == 0);
  CHECK(resumed.output.find(std::to_string(ids.size()) + " cached") != std::string::npos);
}

TEST_CASE("continuation from the converged neighbour takes fewer load steps than solves from rest")
{
  const std::string sweep = "set Pressure sweep = 1e3, 2e3, 3e3, 4e3\n"
                            "set Lateral tip forces = 0.01, 0.02, 0.03";
  int load_steps[2] = {0, 0};
  for (const bool continuation : {true, false})
    {
      TinyDesign design("sweep_continuation",
                        sweep + "\nset Continuation = " + (continuation ? "true" : "false"));
      REQUIRE(design.run("sweep").status == 0);
      const auto database = ActuationDatabase::open(design.database());
      for (const auto &id : database.sample_ids())
        load_steps[continuation] += database.read_sample(id).load_steps;
    }
  // From rest each solve starts at the .prm's initial load factor 0.25; a
  // continued one starts with the same absolute increment, i.e. a larger
  // load factor along its shorter path, and needs fewer steps.
  CHECK(load_steps[true] < load_steps[false]);
}

namespace
{
  using Stored = std::map<std::string, softchain::data::SampleRecord>; // by sample id

  // The samples of `sweep` solved twice: [true] with continuation (chains,
  // inflated starts), [false] each from rest.
  std::map<bool, Stored> solved_both_ways(const std::string &name, const std::string &sweep)
  {
    std::map<bool, Stored> stored;
    for (const bool continuation : {true, false})
      {
        TinyDesign design(name, sweep + "\nset Continuation = " + (continuation ? "true" : "false"));
        REQUIRE(design.run("sweep").status == 0);
        const auto database = ActuationDatabase::open(design.database());
        for (const auto &id : database.sample_ids())
          stored[continuation][id] = database.read_sample(id);
      }
    return stored;
  }

  // The largest node position difference between two solves of one sample.
  // Both end at a relative residual and update of 1e-6, and the tiny
  // bender's nodes move about 1 mm, so the same equilibrium agrees to about
  // 1e-9 m; callers allow 1e-8 m, a hundredth of a micrometre. (Measured:
  // the same bits, Newton having gone to round-off.)
  double node_difference(const softchain::data::SampleRecord &a, const softchain::data::SampleRecord &b)
  {
    double largest = 0;
    for (std::size_t n = 0; n < a.x.size(); ++n)
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(a.x[n][c] - b.x[n][c]));
    return largest;
  }
} // namespace

TEST_CASE("a chain of forces at a pressure starts from that pressure's equilibrium, not from rest")
{
  // The pressure samples are solved first; the lateral chain at 2 kPa then
  // starts from the 2 kPa sample and only its force grows (one load step),
  // where from rest the pressure and the force grow together.
  const auto stored = solved_both_ways("sweep_inflated_start", "set Pressure sweep = 1e3, 2e3\n"
                                                               "set Force sample pressures = 2e3\n"
                                                               "set Lateral tip forces = 0.01, 0.02");
  REQUIRE(stored.at(true).size() == 4);
  for (const auto &[id, record] : stored.at(true))
    {
      const auto &from_rest = stored.at(false).at(id);
      INFO("sample " << id << " at " << record.actuation.pressure << " Pa");
      if (record.actuation.point_forces.empty())
        continue;
      const bool first_of_chain = record.actuation.point_forces[0].force[2] < 0.015;
      if (first_of_chain)
        {
          CHECK(record.load_steps == 1);
          CHECK(from_rest.load_steps > 1);
        }
      CHECK(node_difference(record, from_rest) < 1e-8);
    }
}

TEST_CASE("a 'chord F' sample pulls along the chord of its pressure sample and stays cached")
{
  // The fabric layer makes the bender bend, and its chord turn down.
  TinyDesign design("sweep_chord",
                    "set Pressure sweep = 1e3, 2e3\n"
                    "set Chord samples = 2e3 : tip : chord 0.01 ; 0 : tip : chord 0.01",
                    "subsection Springs\n  set Generate for bender = true\n"
                    "  set Axial rigidity = fabric: 2000, thread: 500\nend\n");
  const auto first = design.run("sweep");
  INFO(first.output);
  REQUIRE(first.status == 0);
  CHECK(first.output.find("4 solved") != std::string::npos);
  const auto database = ActuationDatabase::open(design.database());
  const auto mesh     = database.mesh();
  // The chord, measured here apart from the sweep's code: the tip's position
  // is the mean of the deformed tip nodes (TipPoseFit), the base face's
  // centroid the middle of the rectangle its nodes span (the tiny bender's
  // base is a full rectangle meshed uniformly).
  const auto chord_of = [&](const std::vector<Point3> &x) {
    Point3 tip{0, 0, 0}, low{1, 1, 1}, high{-1, -1, -1};
    for (const auto n : mesh.tip_nodes)
      for (int c = 0; c < 3; ++c)
        tip[c] += x[n][c] / mesh.tip_nodes.size();
    for (const auto n : mesh.base_nodes)
      for (int c = 0; c < 3; ++c)
        {
          low[c]  = std::min(low[c], mesh.X[n][c]);
          high[c] = std::max(high[c], mesh.X[n][c]);
        }
    const Point3 d = minus(tip, {(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2});
    const double length = std::sqrt(dot(d, d));
    return Point3{d[0] / length, d[1] / length, d[2] / length};
  };
  std::map<double, Point3> inflated; // the pressure samples' chords
  inflated[0] = chord_of(mesh.X);
  for (const auto &id : database.sample_ids())
    {
      const auto record = database.read_sample(id);
      if (record.actuation.role == "pressure")
        inflated[record.actuation.pressure] = chord_of(record.x);
    }
  int chords = 0;
  for (const auto &id : database.sample_ids())
    {
      const auto record = database.read_sample(id);
      if (record.actuation.role != "chord")
        continue;
      ++chords;
      INFO("chord sample at " << record.actuation.pressure << " Pa");
      CHECK(record.converged());
      REQUIRE(record.actuation.point_forces.size() == 1);
      const Point3 &f = record.actuation.point_forces[0].force;
      const Point3 &c = inflated.at(record.actuation.pressure);
      // The same sums in another order: rounding only.
      for (int k = 0; k < 3; ++k)
        CHECK(f[k] == Approx(0.01 * c[k]).margin(1e-14));
      // From its pressure sample, only the force grows: one load step.
      if (record.actuation.pressure > 0)
        CHECK(record.load_steps == 1);
    }
  CHECK(chords == 2);
  // The inflated chord turns down with the bending finger.
  CHECK(inflated.at(2e3)[1] < inflated.at(0)[1] - 1e-3);

  const auto rerun = design.run("sweep");
  INFO(rerun.output);
  CHECK(rerun.output.find("4 cached, 0 solved") != std::string::npos);
}

TEST_CASE("a held-out pressure continues from the nearest lower swept pressure, not from rest")
{
  // The inflations share one chain whatever their role: the held-out
  // 1.5 kPa starts from the 1 kPa equilibrium, where from rest it would
  // first inflate the finger through the 1 kPa the sweep already solved.
  const auto stored = solved_both_ways("sweep_held_out_pressure", "set Pressure sweep = 1e3, 2e3\n"
                                                                  "set Validation samples = 1.5e3");
  REQUIRE(stored.at(true).size() == 3);
  int held_out = 0;
  for (const auto &[id, record] : stored.at(true))
    {
      const auto &from_rest = stored.at(false).at(id);
      INFO("sample " << id << " (" << record.actuation.role << ") at " << record.actuation.pressure << " Pa");
      if (record.actuation.role == "validation")
        {
          ++held_out;
          CHECK(record.load_steps < from_rest.load_steps);
        }
      CHECK(node_difference(record, from_rest) < 1e-8);
    }
  CHECK(held_out == 1);
}

TEST_CASE("a sample that does not converge is stored as failed and the sweep exits 2 naming it")
{
  // 1 MN on a 2 cm silicone finger inverts elements at the smallest load step.
  TinyDesign design("sweep_failure", "set Lateral tip forces = 0.01, 1e6");
  const auto outcome = design.run("sweep");
  INFO(outcome.output);
  CHECK(outcome.status == 2);
  CHECK(outcome.output.find("sample failed: lateral 1e+06 N") != std::string::npos);
  const auto database = ActuationDatabase::open(design.database());
  REQUIRE(database.sample_ids().size() == 2);
  int failed = 0;
  for (const auto &id : database.sample_ids())
    {
      const auto s = database.read_sample(id);
      if (s.converged())
        continue;
      ++failed;
      CHECK(!s.reason.empty());
      CHECK(s.load_factor_reached < 1.0);
      CHECK(s.x.size() == database.mesh().X.size()); // the last converged state
    }
  CHECK(failed == 1);
  CHECK(design.run("sweep").status == 2); // cached, still reported
}

TEST_CASE("samples beyond a limit point of their chain are stored as failed without a solve")
{
  // The tiny bender has no thread rings: its walls balloon and pressure
  // control stops at a limit point near 25 kPa (measured 25.3 kPa), so the
  // 40 kPa sample fails there and the 80 kPa sample is past it.
  TinyDesign design("sweep_limit_point", "set Pressure sweep = 10e3, 40e3, 80e3");
  const auto outcome = design.run("sweep");
  INFO(outcome.output);
  CHECK(outcome.status == 2);
  const auto database = ActuationDatabase::open(design.database());
  std::map<double, softchain::data::SampleRecord> by_pressure;
  for (const auto &id : database.sample_ids())
    {
      auto s = database.read_sample(id);
      by_pressure[s.actuation.pressure] = s;
    }
  REQUIRE(by_pressure.size() == 3);
  CHECK(by_pressure[10e3].converged());
  const auto &stop = by_pressure[40e3], &beyond = by_pressure[80e3];
  CHECK(stop.reason.rfind("limit point", 0) == 0);
  CHECK(stop.newton_iterations > 0);
  CHECK(!beyond.converged());
  CHECK(beyond.reason.find("beyond the limit point of sample " + stop.id) != std::string::npos);
  CHECK(beyond.newton_iterations == 0); // not solved
  CHECK(beyond.x == stop.x);            // the state at the limit
}

TEST_CASE("a volume sweep follows the finger past the limit point of its pressure")
{
  // The tiny bender's pressure has a limit point near 25 kPa (test above).
  // Under volume control the cavity keeps growing past it while the pressure
  // that holds it falls (measured: 24.7 kPa at 2 V0, 21.8 kPa at 6 V0).
  TinyDesign design("sweep_volume", "set Volume sweep = 6, 1.25, 2");
  auto       outcome = design.run("sweep");
  INFO(outcome.output);
  REQUIRE(outcome.status == 0);
  const auto database = ActuationDatabase::open(design.database());
  const auto &mesh    = database.mesh();
  // The cavity's volume from its triangles (they point into the cavity).
  const auto volume = [&](const std::vector<Point3> &x) {
    double v = 0.0;
    for (const auto &t : mesh.cavity_triangles)
      v -= dot(x[t[0]], cross(x[t[1]], x[t[2]])) / 6;
    return v;
  };
  std::map<double, softchain::data::SampleRecord> by_ratio;
  for (const auto &id : database.sample_ids())
    {
      auto s = database.read_sample(id);
      REQUIRE(s.actuation.cavity_volume_ratio);
      CHECK(s.actuation.role == "volume");
      CHECK(s.converged());
      by_ratio[*s.actuation.cavity_volume_ratio] = s;
    }
  REQUIRE(by_ratio.size() == 3);
  for (const auto &[ratio, s] : by_ratio)
    {
      INFO("V/V0 = " << ratio << ", p = " << s.actuation.pressure);
      // Volume control meets the volume to Solver/Residual tolerance (1e-6)
      // relative; measured from the stored triangles: 1.4e-11 at most.
      CHECK(volume(s.x) / volume(mesh.X) == Approx(ratio).epsilon(1e-6));
    }
  const double p1 = by_ratio[1.25].actuation.pressure, p2 = by_ratio[2].actuation.pressure,
               p6 = by_ratio[6].actuation.pressure;
  CHECK(p1 > 0);
  CHECK(p2 > p1); // rising towards the limit point
  CHECK(p6 < p2); // past it: more volume at less pressure
  // The ratio names the sample: a rerun finds all three cached, with the
  // pressure found.
  outcome = design.run("sweep");
  CHECK(outcome.status == 0);
  CHECK(softchain::testing::occurrences(outcome.output, " cached (converged)") == 3);
  const auto again = ActuationDatabase::open(design.database());
  for (const auto &[ratio, s] : by_ratio)
    {
      const auto cached = again.read_sample(s.id);
      CHECK(cached.actuation.pressure == s.actuation.pressure);
      CHECK(cached.x == s.x);
    }
}

TEST_CASE("force points outside the body or malformed samples fail with exit 1 before any solve")
{
  TinyDesign design("sweep_bad_point", "set Pressure sweep = 1e3\n"
                                       "set Validation samples = 1e3 : 0.5,0,0 : 0,0,0.01");
  const auto outside = design.run("sweep");
  INFO(outside.output);
  CHECK(outside.status == 1);
  CHECK(outside.output.find("sample 'validation 1': force point 0") != std::string::npos);
  CHECK(outside.output.find("outside the body") != std::string::npos);
  CHECK(!std::filesystem::exists(design.database())); // nothing solved, nothing stored

  const std::pair<const char *, const char *> bad[] = {
    {"set Lateral tip forces = 0.1, abc", "'Lateral tip forces'"},
    {"set Validation samples = 1e3 : tip", "sample 'validation 1': '1e3 : tip' needs 'p'"},
    {"set Pressure sweep = 1e3\nset Validation samples = 1e3",
     "sample 'validation 1' repeats the actuation of sample 'pressure 1000 Pa'"},
    {"set Volume sweep = 1.5, 0.8", "'Volume sweep' in subsection 'Samples': 0.8 is not a volume ratio"}};
  for (const auto &[entry, message] : bad)
    {
      design.write(entry);
      const auto malformed = design.run("sweep");
      INFO(malformed.output);
      CHECK(malformed.status == 1);
      CHECK(malformed.output.find(message) != std::string::npos);
    }
}

TEST_CASE("a sweep on a database that another writer holds stops at once on every rank")
{
  // flock(1) takes the same advisory lock a writing sweep holds; the sweep,
  // serial or on 2 MPI ranks, must exit 1 naming the database, not hang
  // (before, rank 1 waited forever for rank 0's first round).
  TinyDesign design("sweep_locked", samples); // nothing stored yet: all 6 to solve
  std::filesystem::create_directories(design.output());
  const std::string lock   = design.database() + ".lock";
  // In a process group of its own (setsid) with no terminal output, so that ctest does not
  // wait for it and one kill of its process group ends it and its sleep.
  const std::string holder = "setsid flock -n " + lock + " sleep 60 < /dev/null > /dev/null 2>&1 & "
                             "echo $! > " + lock + ".pid";
  REQUIRE(std::system(holder.c_str()) == 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500)); // the holder has the lock
  for (const unsigned int ranks : {1u, 2u})
    {
      const auto outcome = design.run("sweep", ranks);
      INFO(ranks << " rank(s): " << outcome.output);
      CHECK(outcome.status == 1);
      CHECK(outcome.output.find("another writer has it open") != std::string::npos);
      CHECK(outcome.output.find("solved") == std::string::npos); // stopped before any solve
    }
  CHECK(std::system(("kill -- -$(cat " + lock + ".pid)").c_str()) == 0);
}

TEST_CASE("the sweep gives the same database on 1 and 2 MPI ranks")
{
  // With a volume chain: its pressures, found by one group, reach rank 0.
  // By default each rank is a sample group: the chains at 0 Pa and the
  // volume chain are solved beside the inflations, the rest after them,
  // and each group's records reach rank 0 while it solves its own.
  const std::string with_volume = samples + "\nset Volume sweep = 1.5, 2";
  TinyDesign        serial("sweep_serial", with_volume);
  TinyDesign        parallel("sweep_parallel", with_volume);
  sweep_on_one_and_two_ranks(serial, parallel);
  const auto a = ActuationDatabase::open(serial.database());
  const auto b = ActuationDatabase::open(parallel.database());
  // One rank per sample group: every sample is the same serial solve.
  CHECK(softchain::testing::sample_difference(a, b) == "");

  // One group of two ranks: the mesh is partitioned, yet the node numbering
  // and the reference positions are the same bits.
  TinyDesign split("sweep_split", with_volume + "\nset Sample groups = 1");
  REQUIRE(split.run("sweep", 2).status == 0);
  const auto c = ActuationDatabase::open(split.database());
  CHECK(c.mesh().X == a.mesh().X);
  CHECK(c.mesh().cells == a.mesh().cells);
  CHECK(c.mesh().cavity_triangles == a.mesh().cavity_triangles);
  CHECK(c.mesh().tip_nodes == a.mesh().tip_nodes);
  REQUIRE(c.sample_ids() == a.sample_ids());
  // The partitioned solve sums in another order, and one rank solves the
  // load steps before the last inexactly (NewtonSolver's forcing term)
  // where two ranks factorise in double: each answer lies within Newton's
  // displacement tolerance of the exact one, |x* - x| <= 1e-6 |u| (u all
  // of the sample's displacements), so the two within 2e-6 |u| of each
  // other (measured 1e-10 m, 9.6e-8 |u|; 6.6e-16 m, rounding, when both
  // solved every step exactly), far below any numbering or gathering error
  // (>= 1 mm).
  CHECK(relative_position_difference(a, c) <= 2e-6);
}

TEST_CASE("the validation protocol's tip motions give the same samples on 1 and 2 MPI ranks")
{
  // The tip held rigidly (lateral, bending) and by a point contact (twist)
  // on a mesh partitioned in two along its length: one rank owns no tip
  // DoFs. (Before, the held face's constraints crashed that rank and the
  // point contact's update of the tip hung the other.) The bender with its
  // springs, so that the inflation reaches the protocol's tip angle.
  const std::string springs  = "subsection Springs\n  set Generate for bender = true\nend\n";
  const std::string protocol = "subsection Protocol\n  set Tip angle = 10\n  set Lateral amplitude = 0.002\n"
                               "  set Bending amplitude = 0.001\n  set Twist amplitude = 5\n"
                               "  set Steps = 1\nend\n";
  const std::string one_group = "set Pressure sweep = 10e3\nset Sample groups = 1";
  TinyDesign        serial("protocol_serial", one_group, springs + protocol);
  TinyDesign        split("protocol_split", one_group, springs + protocol);
  sweep_on_one_and_two_ranks(serial, split);
  // The protocol's samples in the same order (protocol_samples.csv); their
  // ids differ, since the inflation's pressure and tip frame, which the
  // motions are defined in, differ in the last digits.
  const auto a     = ActuationDatabase::open(serial.database());
  const auto b     = ActuationDatabase::open(split.database());
  const auto rows  = CsvTable::read(serial.output() + "/protocol_samples.csv");
  const auto other = CsvTable::read(split.output() + "/protocol_samples.csv");
  REQUIRE(rows.n_rows() == 7); // the inflation and six tip motions
  REQUIRE(other.n_rows() == rows.n_rows());
  double largest = 0.0;
  for (std::size_t r = 0; r < rows.n_rows(); ++r)
    {
      CHECK(rows.text(r, "motion") == other.text(r, "motion"));
      const auto x = a.read_sample(rows.text(r, "sample"));
      const auto y = b.read_sample(other.text(r, "sample"));
      REQUIRE(x.converged());
      REQUIRE(y.converged());
      for (std::size_t n = 0; n < x.x.size(); ++n)
        for (int c = 0; c < 3; ++c)
          largest = std::max(largest, std::abs(x.x[n][c] - y.x[n][c]));
    }
  // Within Newton's tolerances, as the partitioned sweep above (1e-6 of the
  // ~10 mm displacements), far below a wrong motion (>= the 1 mm amplitude).
  CHECK(largest < 1e-8);
}
