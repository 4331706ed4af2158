// The contact section's figures: the curve plot's axis bounds and series,
// and the obstacles' outlines, which must lie on the obstacles' surfaces.
#include <softchain/report/obstacle_outline.h>
#include <softchain/report/svg_curve_plot.h>

#include "../data/occurrences.h"

#include <catch2/catch.hpp>

using namespace softchain::report;

TEST_CASE("A curve plot's axes end at 1, 2 or 5 times a power of ten, and each series is one polyline")
{
  CHECK(SvgCurvePlot::nice_bound(0.813) == Approx(1.0));
  CHECK(SvgCurvePlot::nice_bound(1.126) == Approx(2.0));
  CHECK(SvgCurvePlot::nice_bound(3.0) == Approx(5.0));
  CHECK(SvgCurvePlot::nice_bound(50.0) == Approx(50.0));
  CHECK(SvgCurvePlot::nice_bound(0.0021) == Approx(0.005));
  SvgCurvePlot plot("p [kPa]", "F [N]");
  plot.add("table", {{10, 0.1}, {20, 0.4}, {30, 0.8}});
  plot.add("can & co", {{10, 0.2}, {20, NAN}});
  const std::string svg = plot.render("blocked force");
  CHECK(softchain::testing::occurrences(svg, "<polyline") == 2);
  CHECK(softchain::testing::occurrences(svg, "<circle") == 4); // the NaN point is left out
  CHECK(svg.find("can &amp; co") != std::string::npos);
  CHECK(svg.find(">30<") != std::string::npos); // the x axis ends at 30
}

TEST_CASE("An obstacle's outline lies on its surface, at the end of its motion")
{
  const Eigen::AlignedBox3d finger(Eigen::Vector3d(0, 0, -0.01), Eigen::Vector3d(0.09, 0.02, 0.01));
  const softchain::data::ObstacleRecord table{"table", "plane", {0, -0.005, 0}, {0, 2, 0}, 0, {}, 0, {0, 0.001, 0}};
  const auto plane = obstacle_outline(table, finger);
  REQUIRE(plane.size() == 1);
  REQUIRE(plane[0].size() == 4);
  for (const auto &x : plane[0])
    CHECK(x.y() == Approx(-0.004));
  const softchain::data::ObstacleRecord can{"can", "cylinder", {0.055, -0.015, 0}, {0, 0, 1}, 0.01, {}, 0, {}};
  const auto cylinder = obstacle_outline(can, finger);
  CHECK(cylinder.size() == 2 + 32); // two end discs and the quads between them
  for (const auto &piece : cylinder)
    for (const auto &x : piece)
      CHECK(std::hypot(x.x() - 0.055, x.y() + 0.015) == Approx(0.01));
  const softchain::data::ObstacleRecord block{"block", "box", {0, 0, 0}, {}, 0, {1, 2, 3}, 0, {}};
  const auto box = obstacle_outline(block, finger);
  REQUIRE(box.size() == 6);
  for (const auto &face : box)
    for (const auto &x : face)
      CHECK((std::abs(std::abs(x.x()) - 1) + std::abs(std::abs(x.y()) - 2) + std::abs(std::abs(x.z()) - 3)) < 1e-12);
  // Turned by 90 degrees about z, its corners lie at (+-2, +-1, +-3).
  const softchain::data::ObstacleRecord turned{"block", "box", {0, 0, 0}, {}, 0, {1, 2, 3}, 0, {}, {0, 0, M_PI / 2}};
  for (const auto &face : obstacle_outline(turned, finger))
    for (const auto &x : face)
      CHECK((std::abs(std::abs(x.x()) - 2) + std::abs(std::abs(x.y()) - 1) + std::abs(std::abs(x.z()) - 3)) < 1e-12);
}
