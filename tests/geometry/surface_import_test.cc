// A design imported from two closed STL surfaces: a box-shaped body with a
// cylindrical cavity along x, tetrahedralised with the same groups.
#include <softchain/data/input_error.h>
#include <softchain/geometry/cavity_surface.h>
#include <softchain/geometry/cell_geometry.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/msh_file.h>
#include <softchain/geometry/stl_file.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;
using Catch::Matchers::Contains;

namespace
{
  const double length = 0.06, width = 0.02, height = 0.016; // body box, m
  const double cavity_start = 0.01, cavity_end = 0.05, radius = 0.005;
  const Eigen::Vector3d axis_point(0.0, 0.008, 0.0); // cavity axis: y = 0.008, z = 0
  const int             n_segments = 24;

  void add_quad(StlFile &stl, const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                const Eigen::Vector3d &c, const Eigen::Vector3d &d)
  {
    stl.triangles.push_back({a, b, c});
    stl.triangles.push_back({a, c, d});
  }

  StlFile box()
  {
    StlFile    stl;
    const auto p = [](int i, int j, int k) {
      return Eigen::Vector3d(i * length, j * height, (k - 0.5) * width);
    };
    add_quad(stl, p(0, 0, 0), p(0, 1, 0), p(0, 1, 1), p(0, 0, 1)); // base, x = 0
    add_quad(stl, p(1, 0, 0), p(1, 0, 1), p(1, 1, 1), p(1, 1, 0)); // tip, x = length
    add_quad(stl, p(0, 0, 0), p(0, 0, 1), p(1, 0, 1), p(1, 0, 0));
    add_quad(stl, p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1));
    add_quad(stl, p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0));
    add_quad(stl, p(0, 0, 1), p(0, 1, 1), p(1, 1, 1), p(1, 0, 1));
    return stl;
  }

  // Cylinder inscribed in the circle of `radius`: a prism on a regular polygon.
  StlFile cylinder()
  {
    StlFile    stl;
    const auto rim = [](double x, int i) {
      const double angle = 2.0 * M_PI * i / n_segments;
      return Eigen::Vector3d(x, axis_point.y() + radius * std::cos(angle), radius * std::sin(angle));
    };
    const Eigen::Vector3d start(cavity_start, axis_point.y(), 0), end(cavity_end, axis_point.y(), 0);
    for (int i = 0; i < n_segments; ++i)
      {
        add_quad(stl, rim(cavity_start, i), rim(cavity_end, i), rim(cavity_end, i + 1),
                 rim(cavity_start, i + 1));
        stl.triangles.push_back({start, rim(cavity_start, i + 1), rim(cavity_start, i)});
        stl.triangles.push_back({end, rim(cavity_end, i), rim(cavity_end, i + 1)});
      }
    return stl;
  }

  std::string imported_design(const std::string &dir, const std::string &tip_plane)
  {
    box().write(dir + "/body.stl");
    cylinder().write(dir + "/cavity.stl");
    const std::string path = dir + "/imported.prm";
    write_text(path, "subsection Finger design\n"
                     "  set Shape = stl\n"
                     "  set Resolution = 0\n"
                     "  set Mesh sizes = 0.006, 0.003, 0.0015\n"
                     "  set Outer surface file = body.stl\n"
                     "  set Cavity surface file = cavity.stl\n"
                     "  set Base plane x = 0\n"
                     "  set Tip plane x = " + tip_plane + "\n"
                     "end\n");
    return path;
  }
} // namespace

TEST_CASE("an STL design is tetrahedralised with the groups and volumes of its surfaces",
          "[geometry][import]")
{
  const std::string     dir = scratch_directory("import");
  GmshMesher            mesher(dir + "/cache");
  const GeneratedDesign generated =
    generate_design(FingerDesign::read(imported_design(dir, "0.06")), mesher);
  const MshFile mesh = MshFile::read(generated.mesh_file);
  CHECK(generated.length == length);
  for (const char *name : {"base", "cavity", "tip"})
    CHECK(mesh.has_group(name, 2));
  for (const MshElement *facet : mesh.facets_of("tip"))
    for (const std::size_t n : facet->nodes)
      REQUIRE(mesh.nodes[n].x() == Approx(length).margin(1e-12));

  // The polygonal cavity is enclosed exactly (flat facets: round-off only,
  // see planar_volume_tolerance in parametric_mesh_test.cc).
  const double theta   = 2.0 * M_PI / n_segments;
  const double polygon = 0.5 * n_segments * radius * radius * std::sin(theta) * (cavity_end - cavity_start);
  const CavitySurface cavity(mesh);
  CHECK(cavity.enclosed_volume() == Approx(polygon).epsilon(1e-12));
  CHECK(CellGeometry::total_volume(mesh) ==
        Approx(length * width * height - polygon).epsilon(1e-12));
  // Against the round cylinder the chords lose 1 - sin(theta)/theta of the
  // area, at most theta^2 / 6 (1.1 % at 24 segments).
  const double cylinder_volume = M_PI * radius * radius * (cavity_end - cavity_start);
  CHECK(std::abs(cavity.enclosed_volume() - cylinder_volume) <= theta * theta / 6 * cylinder_volume);
}

TEST_CASE("an STL design whose tip plane holds no triangle is refused", "[geometry][import]")
{
  const std::string dir = scratch_directory("import_bad_plane");
  GmshMesher        mesher(dir + "/cache");
  CHECK_THROWS_WITH(generate_design(FingerDesign::read(imported_design(dir, "0.05")), mesher),
                    Contains("body.stl") && Contains("Tip plane x"));
  CHECK(mesher.n_runs() == 0);
}
