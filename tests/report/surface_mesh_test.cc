// SurfaceMesh: the faces used by one cell only, oriented out of their cell.
#include <softchain/data/input_error.h>
#include <softchain/report/surface_mesh.h>

#include <catch2/catch.hpp>

#include "../chain/box_mesh.h"

#include <Eigen/Geometry>

using softchain::chain::testing::box_mesh;
using softchain::chain::testing::BoxMeshSpec;
using softchain::report::SurfaceMesh;

namespace
{
  // nx x ny x nz unit cells, hexahedra or each split into 6 tetrahedra.
  softchain::data::MeshRecord blocks(const int nx, const int ny, const int nz, const bool tetrahedra)
  {
    BoxMeshSpec spec;
    spec.length = nx, spec.height = ny, spec.width = nz, spec.y0 = 0;
    spec.nx = nx, spec.ny = ny, spec.nz = nz, spec.tetrahedra = tetrahedra;
    return box_mesh(spec);
  }

  Eigen::Vector3d at(const softchain::data::MeshRecord &mesh, const std::int64_t node)
  {
    return {mesh.X[node][0], mesh.X[node][1], mesh.X[node][2]};
  }

  // Every face's normal points away from the centre of the (convex) box.
  bool all_outward(const softchain::data::MeshRecord &mesh, const SurfaceMesh &surface)
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (std::size_t n = 0; n < mesh.X.size(); ++n)
      centre += at(mesh, n) / mesh.X.size();
    for (const auto &face : surface.faces())
      {
        const Eigen::Vector3d normal =
          (at(mesh, face[1]) - at(mesh, face[0])).cross(at(mesh, face[2]) - at(mesh, face[0]));
        if (normal.dot(at(mesh, face[0]) - centre) <= 0)
          return false;
      }
    return true;
  }
} // namespace

TEST_CASE("The boundary of hexahedra: 6 faces of one cell, 10 of two sharing a face")
{
  for (const auto &[nx, expected] : {std::pair{1, 6u}, std::pair{2, 10u}})
    {
      const auto        mesh = blocks(nx, 1, 1, false);
      const SurfaceMesh surface(mesh);
      CHECK(surface.faces().size() == expected);
      for (const auto &face : surface.faces())
        CHECK(face.size() == 4);
      CHECK(all_outward(mesh, surface));
    }
}

TEST_CASE("The boundary of tetrahedra: two triangles per square of the box's surface")
{
  // A cube split into 6 tetrahedra around its diagonal: each of its 6
  // squares is covered by 2 triangles; the 12 inner triangles are shared.
  for (const auto &[nx, expected] : {std::pair{1, 12u}, std::pair{2, 20u}})
    {
      const auto        mesh = blocks(nx, 1, 1, true);
      const SurfaceMesh surface(mesh);
      CHECK(surface.faces().size() == expected);
      CHECK(all_outward(mesh, surface));
    }
}

TEST_CASE("A hollow box has its cavity walls on the boundary too")
{
  // 3 x 3 cells in the cross-section, the middle one a tunnel along x
  // through 2 cells: outer skin 2 (2*3 + 3*3 + 2*3) = 42 squares, less the
  // 2 tunnel mouths, plus the tunnel's 4 walls along 2 cells.
  BoxMeshSpec spec;
  spec.nx = 2, spec.ny = 3, spec.nz = 3, spec.wall_cells = 1;
  CHECK(SurfaceMesh(box_mesh(spec)).faces().size() == 42 - 2 + 8);
}

TEST_CASE("Cells of another node count are an input error")
{
  auto mesh           = blocks(1, 1, 1, false);
  mesh.nodes_per_cell = 6;
  mesh.cells.resize(6);
  CHECK_THROWS_AS(SurfaceMesh(mesh), softchain::data::InputError);
}
