// SvgFingerRenderer: painter's order, back faces dropped, one picture per state.
#include <softchain/report/svg_finger_renderer.h>

#include <catch2/catch.hpp>

#include "../data/occurrences.h"
#include "../chain/box_mesh.h"

#include <regex>

using softchain::report::SurfaceMesh;
using softchain::report::SvgFingerRenderer;

namespace
{
  softchain::data::MeshRecord unit_cube()
  {
    softchain::chain::testing::BoxMeshSpec spec;
    spec.length = spec.height = spec.width = 1, spec.y0 = 0;
    spec.nx = spec.ny = spec.nz = 1;
    return softchain::chain::testing::box_mesh(spec);
  }
} // namespace

TEST_CASE("Painter's order: farthest (smallest depth) first, ties in their order")
{
  CHECK(SvgFingerRenderer::far_to_near({0.5, -1, 2, -1}) == std::vector<std::size_t>{1, 3, 0, 2});
  CHECK(SvgFingerRenderer::far_to_near({}).empty());
}

TEST_CASE("A cube seen obliquely shows three shaded faces, nearest last")
{
  const auto        mesh = unit_cube();
  SvgFingerRenderer renderer(SurfaceMesh(mesh), mesh.X);
  const std::string svg = renderer.render(mesh.X, "cube");
  // The default view looks from +x, +y, +z: the three faces whose outward
  // normals are +x, +y, +z face the viewer, the other three are dropped;
  // the rest shape (the same cube) adds three unshaded ones.
  CHECK(softchain::testing::occurrences(svg, "<polygon") == 6);
  CHECK(softchain::testing::occurrences(svg, "fill=\"rgb(") == 3);
  // Face centroids' depths along the view direction w ~ (0.35, 0.45, 1):
  // +x face 1.075, +y face 1.125, +z face 1.4 (over |w|), so the painter
  // draws them in that order. Lambert's law with the renderer's light
  // l ~ (-0.3, 0.8, 1) gives brightness 0.35 + 0.65 max(0, n.l): 0.35,
  // 0.745, 0.844, i.e. red channels of 236 * that: 83, 176, 199.
  const std::regex shaded("<polygon[^>]*fill=\"rgb\\((\\d+),");
  std::vector<int> reds;
  for (std::sregex_iterator m(svg.begin(), svg.end(), shaded), end; m != end; ++m)
    reds.push_back(std::stoi((*m)[1]));
  CHECK(reds == std::vector<int>{83, 176, 199});
  CHECK(svg.find("cube</text>") != std::string::npos);
}

TEST_CASE("Every picture of one renderer shares the frame that holds all states")
{
  const auto mesh  = unit_cube();
  auto       moved = mesh.X;
  for (auto &x : moved)
    x[1] -= 3; // far below the rest shape
  SvgFingerRenderer alone(SurfaceMesh(mesh), mesh.X);
  SvgFingerRenderer shared(SurfaceMesh(mesh), mesh.X);
  shared.include(moved);
  // The rest shape is drawn smaller once the frame must hold the moved cube.
  CHECK(alone.render(mesh.X, "") != shared.render(mesh.X, ""));
  CHECK(shared.render(mesh.X, "") == shared.render(mesh.X, ""));
}

TEST_CASE("A chain is drawn on top as a polyline through its projected points")
{
  const auto        mesh = unit_cube();
  SvgFingerRenderer renderer(SurfaceMesh(mesh), mesh.X);
  const std::string plain = renderer.render(mesh.X, "cube");
  CHECK(plain.find("<polyline") == std::string::npos);
  // The cube's corners 0 and 7 span the frame: their pixels are where the
  // frame maps them, the same for the chain as for the faces.
  const std::string svg = renderer.render(mesh.X, "cube", {{0, 0, 0}, {0.5, 0.5, 0.5}, {1, 1, 1}});
  CHECK(softchain::testing::occurrences(svg, "<polyline") == 1);
  CHECK(softchain::testing::occurrences(svg, "<circle") == 3);
  // Drawn after (on top of) every face.
  CHECK(svg.find("<polyline") > svg.rfind("<polygon"));
  // The middle point projects to the middle of the two others (a parallel
  // projection is affine), to the 0.1 px the SVG prints.
  const std::regex circle("<circle cx=\"([0-9.]+)\" cy=\"([0-9.]+)\"");
  std::vector<Eigen::Vector2d> centres;
  for (std::sregex_iterator m(svg.begin(), svg.end(), circle), end; m != end; ++m)
    centres.emplace_back(std::stod((*m)[1]), std::stod((*m)[2]));
  REQUIRE(centres.size() == 3);
  CHECK((centres[1] - 0.5 * (centres[0] + centres[2])).norm() < 0.1);
}
