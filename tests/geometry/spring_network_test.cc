// The spring network file (exact round trip, named errors) and the layout of
// the fabric and thread networks generated from the finger dimensions.
#include <softchain/data/input_error.h>
#include <softchain/geometry/reinforcement.h>
#include <softchain/geometry/spring_network_file.h>

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
  const std::vector<SpringNetwork> networks{Reinforcement::fabric(design.dimensions, design.springs),
                                            Reinforcement::threads(design.dimensions, design.springs)};
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
