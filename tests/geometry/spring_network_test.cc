// The spring network file (exact round trip, named errors) and the layout of
// the fabric and thread networks generated from the finger dimensions.
#include <softchain/data/input_error.h>
#include <softchain/geometry/reinforcement.h>
#include <softchain/geometry/spring_network_file.h>

#include <Eigen/Geometry> // cross products
#include <catch2/catch.hpp>

#include <cmath>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;
using Catch::Matchers::Contains;

namespace
{
  FingerDesign p10()
  {
    return FingerDesign::read(source_path("parameter_files/p10.prm"));
  }
} // namespace

TEST_CASE("spring network files read back exactly what was written", "[geometry][springs]")
{
  const FingerDesign               design = p10();
  const std::vector<SpringNetwork> networks{
    Reinforcement::fabric(design.dimensions, design.springs),
    Reinforcement::threads(design.dimensions, design.springs),
    Reinforcement::fabric_sheet(design.dimensions, design.springs),
    Reinforcement::thread_sheets(design.dimensions, design.springs)};
  const std::string path = scratch_directory("springs_round_trip") + "/springs.txt";
  SpringNetworkFile::write(path, networks);
  const auto back = SpringNetworkFile::read(path);
  REQUIRE(back.size() == networks.size());
  for (std::size_t n = 0; n < networks.size(); ++n)
    {
      CHECK(back[n].name == networks[n].name);
      REQUIRE(back[n].polylines.size() == networks[n].polylines.size());
      for (std::size_t l = 0; l < networks[n].polylines.size(); ++l)
        {
          CHECK(back[n].polylines[l].closed == networks[n].polylines[l].closed);
          // Bitwise equal: 17 significant digits round-trip a double.
          REQUIRE(back[n].polylines[l].points == networks[n].polylines[l].points);
        }
      REQUIRE(back[n].sheets.size() == networks[n].sheets.size());
      for (std::size_t s = 0; s < networks[n].sheets.size(); ++s)
        {
          const FibreSheet &a = back[n].sheets[s], &b = networks[n].sheets[s];
          REQUIRE(a.corners == b.corners);
          REQUIRE(a.families.size() == b.families.size());
          for (std::size_t f = 0; f < a.families.size(); ++f)
            {
              CHECK(a.families[f].direction == b.families[f].direction);
              CHECK(a.families[f].spacing == b.families[f].spacing);
            }
        }
    }
}

TEST_CASE("malformed spring network files are named with their line", "[geometry][springs][errors]")
{
  const std::string dir   = scratch_directory("springs_errors");
  const auto        error = [&](const std::string &name, const std::string &text) {
    write_text(dir + "/" + name, text);
    return SpringNetworkFile::read(dir + "/" + name);
  };
  const std::string header = "# SoftChain spring network v1\n";
  CHECK_THROWS_WITH(error("header.txt", "network fabric\n"), Contains("header.txt:1"));
  CHECK_THROWS_WITH(error("short.txt", header + "network fabric\npolyline open 2\n0 0 0\n"),
                    Contains("short.txt:4") && Contains("2 nodes"));
  CHECK_THROWS_WITH(error("kind.txt", header + "network fabric\npolyline ring 1\n0 0 0\n"),
                    Contains("kind.txt:3"));
  CHECK_THROWS_WITH(error("orphan.txt", header + "polyline open 1\n0 0 0\n"), Contains("orphan.txt:2"));
  CHECK_THROWS_WITH(error("extra.txt", header + "network a\npolyline open 1\n0 0 0 0\n"),
                    Contains("extra.txt:4"));
  const std::string sheet = header + "network a\nsheet 3 1\n0 0 0\n1 0 0\n0 1 0\n";
  CHECK_THROWS_WITH(error("two_corners.txt", header + "network a\nsheet 2 1\n"),
                    Contains("two_corners.txt:3") && Contains("3 corners"));
  CHECK_THROWS_WITH(error("no_family.txt", sheet), Contains("no_family.txt:6") && Contains("fibre"));
  CHECK_THROWS_WITH(error("spacing.txt", sheet + "fibre 1 0 0 0\n"), Contains("spacing.txt:7"));
  CHECK_THROWS_WITH(error("direction.txt", sheet + "fibre 0 0 0 0.002\n"), Contains("direction.txt:7"));
}

namespace
{
  double polygon_area(const std::vector<Eigen::Vector3d> &c)
  {
    Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < c.size(); ++k)
      twice_area += (c[k] - c[0]).cross(c[(k + 1) % c.size()] - c[0]);
    return 0.5 * twice_area.norm();
  }

  // Every corner in the silicone, the corners in one plane, each fibre
  // direction a unit vector in it (to round-off of m-sized coordinates).
  void check_sheet(const FingerDimensions &d, const FibreSheet &sheet)
  {
    const Eigen::Vector3d n =
      (sheet.corners[1] - sheet.corners[0]).cross(sheet.corners[2] - sheet.corners[0]).normalized();
    for (const auto &p : sheet.corners)
      {
        REQUIRE(d.material_margin(p) > 0.0);
        REQUIRE(std::abs(n.dot(p - sheet.corners[0])) <= 1e-15);
      }
    for (const auto &f : sheet.families)
      {
        REQUIRE(std::abs(f.direction.norm() - 1) <= 1e-15);
        REQUIRE(std::abs(f.direction.dot(n)) <= 1e-15);
      }
  }
} // namespace

// The sheets hold the springs' fibres where the springs lie: the fabric's
// plane from half a wall from the base to half a wall from the tip, two
// families a fabric spacing apart; the threads' rectangle (bottom-layer
// middle, wall middles) swept over the cavity with hoop fibres, as much
// thread per unit length of finger as the rings: the strips' area over their
// fibre spacing, times the pitch, is the ring's perimeter integrated over the
// cavity (linear in x: the trapezoid rule is exact).
TEST_CASE("the sheets cover the fabric's plane and the threads' walls", "[geometry][springs][sheets]")
{
  const FingerDesign      design = p10();
  const FingerDimensions &d      = design.dimensions;
  const SpringLayout     &layout = design.springs;

  const SpringNetwork fabric = Reinforcement::fabric_sheet(d, layout);
  CHECK(fabric.name == "fabric");
  CHECK(fabric.polylines.empty());
  REQUIRE(fabric.sheets.size() == 1);
  const FibreSheet &sheet = fabric.sheets[0];
  check_sheet(d, sheet);
  for (const auto &p : sheet.corners)
    CHECK(p.y() == layout.fabric_height);
  CHECK(sheet.corners[0].x() == Approx(0.5 * d.wall));
  CHECK(sheet.corners[1].x() == Approx(d.length - 0.5 * d.wall));
  REQUIRE(sheet.families.size() == 2);
  for (const auto &f : sheet.families)
    CHECK(f.spacing == layout.fabric_spacing);

  const SpringNetwork threads = Reinforcement::thread_sheets(d, layout);
  CHECK(threads.name == "thread");
  REQUIRE(threads.sheets.size() == 4);
  double thread_length = 0;
  for (const auto &strip : threads.sheets)
    {
      check_sheet(d, strip);
      REQUIRE(strip.families.size() == 1);
      // At least a pitch apart (more where the strip slopes with the taper).
      CHECK(strip.families[0].spacing >= layout.thread_pitch);
      // The hoop direction is the ring's: normal to the finger's axis.
      CHECK(std::abs(strip.families[0].direction.x()) <= 1e-15);
      thread_length += polygon_area(strip.corners) / strip.families[0].spacing;
    }
  const auto perimeter = [&](double x) {
    return 2 * (d.width(x) - d.wall) + 2 * (d.height(x) - 0.5 * d.wall - 0.5 * d.bottom);
  };
  const double x0 = d.cavity_start(), x1 = d.cavity_end();
  CHECK(thread_length * layout.thread_pitch ==
        Approx(0.5 * (perimeter(x0) + perimeter(x1)) * (x1 - x0)).epsilon(1e-12));
}


TEST_CASE("thread rings are closed, one per pitch, in the walls around the cavity",
          "[geometry][springs]")
{
  const FingerDesign      design  = p10();
  const FingerDimensions &d       = design.dimensions;
  const SpringNetwork     threads = Reinforcement::threads(d, design.springs);
  REQUIRE(threads.polylines.size() >= 2);
  for (std::size_t r = 0; r < threads.polylines.size(); ++r)
    {
      const auto  &ring = threads.polylines[r];
      const double x    = ring.points.front().x();
      CHECK(ring.closed);
      CHECK(x > d.cavity_start());
      CHECK(x < d.cavity_end());
      if (r > 0)
        CHECK(x - threads.polylines[r - 1].points.front().x() ==
              Approx(design.springs.thread_pitch).epsilon(1e-12));
      for (std::size_t i = 0; i < ring.points.size(); ++i)
        {
          const Eigen::Vector3d &p = ring.points[i], &q = ring.points[(i + 1) % ring.points.size()];
          REQUIRE(p.x() == x);
          // Half a wall thickness from the faces, at most the node spacing apart.
          REQUIRE(d.material_margin(p) >= 0.5 * std::min(d.wall, d.bottom) - 1e-12);
          REQUIRE((q - p).norm() <= design.springs.thread_node_spacing * (1 + 1e-12));
        }
    }
  // The rings reach the last pitch before the tip cap.
  CHECK(threads.polylines.back().points.front().x() + design.springs.thread_pitch >= d.cavity_end());
}

TEST_CASE("the fabric is a grid in the bottom layer spanning the finger", "[geometry][springs]")
{
  const FingerDesign      design = p10();
  const FingerDimensions &d      = design.dimensions;
  const SpringNetwork     fabric = Reinforcement::fabric(d, design.springs);
  double                  x_min = 1, x_max = -1;
  for (const auto &line : fabric.polylines)
    {
      CHECK_FALSE(line.closed);
      for (std::size_t i = 0; i < line.points.size(); ++i)
        {
          const Eigen::Vector3d &p = line.points[i];
          REQUIRE(p.y() == design.springs.fabric_height);
          REQUIRE(d.material_margin(p) > 0.0);
          // At most the fabric spacing apart; along x the taper tilts the
          // longitudinal lines by |dz/dx| < 0.03, lengthening a step < 0.1 %.
          if (i > 0)
            REQUIRE((p - line.points[i - 1]).norm() <= design.springs.fabric_spacing * 1.001);
          x_min = std::min(x_min, p.x());
          x_max = std::max(x_max, p.x());
        }
    }
  // Base to tip, half a wall from the end faces.
  CHECK(x_min == Approx(0.5 * d.wall));
  CHECK(x_max == Approx(d.length - 0.5 * d.wall));
}
