// Inverted and distorted cells: the corner test of
// cell_orientation.h on meshes with a known answer, and the refusal of an
// inverted cell before any solve.
#include <softchain/fem/cell_orientation.h>
#include <softchain/data/input_error.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // 4 x 2 x 2 unit cubes: vertex (1, 1, 1) is interior.
  void block(Triangulation<3> &mesh)
  {
    GridGenerator::subdivided_hyper_rectangle(mesh, {4, 2, 2}, Point<3>(), Point<3>(4, 2, 2));
  }

  // Moves the vertex at `from` by `shift`.
  void move_vertex(Triangulation<3> &mesh, const Point<3> &from, const Tensor<1, 3> &shift)
  {
    for (auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(from) < 1e-12)
          cell->vertex(v) = from + shift;
  }
} // namespace

TEST_CASE("the scaled Jacobian is 1 for boxes, in (0, 1) for a distorted cell, <= 0 when inverted",
          "[fem][mesh]")
{
  Triangulation<3> mesh;
  block(mesh);
  // Exact for boxes up to round-off of unit edge lengths.
  CHECK(smallest_scaled_jacobian(mesh) == Approx(1.0).epsilon(1e-14));
  CHECK_NOTHROW(check_cell_orientation(mesh, "box"));

  // The interior vertex moved by half an edge along x: the cells beside it
  // are skewed but not folded.
  Triangulation<3> skewed;
  block(skewed);
  move_vertex(skewed, Point<3>(1, 1, 1), Tensor<1, 3>({0.5, 0, 0}));
  const double q = smallest_scaled_jacobian(skewed);
  CHECK(q > 0);
  CHECK(q < 1);
  CHECK_NOTHROW(check_cell_orientation(skewed, "skewed"));

  // Moved by 1.5 edges: it passes the far face of the cells on its +x side,
  // whose corner edge along +x at that vertex now points backwards.
  Triangulation<3> inverted;
  block(inverted);
  move_vertex(inverted, Point<3>(1, 1, 1), Tensor<1, 3>({1.5, 0, 0}));
  CHECK(smallest_scaled_jacobian(inverted) <= 0);
  CHECK_THROWS_WITH(check_cell_orientation(inverted, "test.msh"),
                    Catch::Contains("test.msh: cell") && Catch::Contains("is inverted"));
}

TEST_CASE("20 % random node jitter distorts but does not invert a tetrahedral or hexahedral mesh",
          "[fem][mesh]")
{
  for (const bool tetrahedra : {false, true})
    {
      Triangulation<3> hexes, mesh;
      GridGenerator::subdivided_hyper_rectangle(hexes, {8, 4, 4}, Point<3>(), Point<3>(8, 4, 4));
      if (tetrahedra)
        GridGenerator::convert_hypercube_to_simplex_mesh(hexes, mesh);
      else
        mesh.copy_triangulation(hexes);
      const double regular = smallest_scaled_jacobian(mesh);
      GridTools::distort_random(0.2, mesh, true);
      const double jittered = smallest_scaled_jacobian(mesh);
      INFO((tetrahedra ? "tetrahedra" : "hexahedra") << ": " << regular << " -> " << jittered);
      // Each node moves by at most 0.2 of its shortest edge, so no cell can
      // fold (that needs a node to cross half a cell), but the shape changes.
      CHECK(jittered > 0);
      CHECK(jittered < regular);
      CHECK_NOTHROW(check_cell_orientation(mesh, "jittered"));
    }
}
