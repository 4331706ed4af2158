// STL surfaces: binary and ASCII reading, and the midpoint subdivision that
// SurfaceImport relies on (area kept, the surface stays conforming).
#include <softchain/data/input_error.h>
#include <softchain/geometry/stl_file.h>

#include <Eigen/Geometry> // cross products
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <map>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;

namespace
{
  // A closed tetrahedron surface with outward triangles.
  StlFile tetrahedron()
  {
    const Eigen::Vector3d a(0, 0, 0), b(0.01, 0, 0), c(0, 0.02, 0), d(0, 0, 0.03);
    StlFile               stl;
    stl.triangles = {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}};
    return stl;
  }

  double area(const StlFile &stl)
  {
    double sum = 0;
    for (const auto &t : stl.triangles)
      sum += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
    return sum;
  }

  // Binary STL bytes written by hand: header, count, 50 bytes per facet.
  std::string binary_bytes(const StlFile &stl)
  {
    std::string         bytes(80, ' ');
    const std::uint32_t n = stl.triangles.size();
    bytes.append(reinterpret_cast<const char *>(&n), 4);
    for (const auto &t : stl.triangles)
      {
        std::array<float, 12> values{}; // normal (zero), then the vertices
        for (int v = 0; v < 3; ++v)
          for (int c = 0; c < 3; ++c)
            values[3 + 3 * v + c] = static_cast<float>(t[v][c]);
        bytes.append(reinterpret_cast<const char *>(values.data()), 48);
        bytes.append(2, '\0');
      }
    return bytes;
  }
} // namespace

TEST_CASE("STL files are read in binary and ASCII form", "[geometry][stl]")
{
  const std::string dir = scratch_directory("stl_read");
  const StlFile     original = tetrahedron();
  write_text(dir + "/binary.stl", binary_bytes(original));
  original.write(dir + "/ascii.stl");
  const StlFile binary = StlFile::read(dir + "/binary.stl");
  const StlFile ascii  = StlFile::read(dir + "/ascii.stl");
  REQUIRE(binary.triangles.size() == 4);
  REQUIRE(ascii.triangles.size() == 4);
  for (std::size_t f = 0; f < 4; ++f)
    for (int v = 0; v < 3; ++v)
      {
        // float32 keeps 24 bits: 6e-8 relative of the 0.03 m extent.
        CHECK((binary.triangles[f][v] - original.triangles[f][v]).norm() < 0.03 * 6e-8);
        CHECK(ascii.triangles[f][v] == original.triangles[f][v]); // 17 digits: exact
      }
  write_text(dir + "/broken.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n");
  CHECK_THROWS_AS(StlFile::read(dir + "/broken.stl"), softchain::data::InputError);
}

TEST_CASE("midpoint subdivision keeps the area and a conforming closed surface", "[geometry][stl]")
{
  const StlFile original = tetrahedron();
  const StlFile fine     = original.subdivided(3);
  CHECK(fine.triangles.size() == 4 * 64);
  CHECK(area(fine) == Approx(area(original)).epsilon(1e-14));
  CHECK(fine.longest_edge() == Approx(original.longest_edge() / 8).epsilon(1e-14));
  // Conforming and closed: every edge (by its exact end points) belongs to
  // exactly two triangles, traversed once in each direction.
  std::map<std::array<double, 6>, int> directed;
  for (const auto &t : fine.triangles)
    for (int e = 0; e < 3; ++e)
      {
        const Eigen::Vector3d &p = t[e], &q = t[(e + 1) % 3];
        ++directed[{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()}];
      }
  for (const auto &[edge, count] : directed)
    {
      REQUIRE(count == 1);
      REQUIRE(directed.count({edge[3], edge[4], edge[5], edge[0], edge[1], edge[2]}) == 1);
    }
}
