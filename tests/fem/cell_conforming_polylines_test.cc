// cell_conforming_polylines(): every link of a split spring polyline lies in
// one cell, the split points lie on the original segments, and on the
// built-in bender the springs then add no entry to the tangent's sparsity
// pattern.
#include "fem_test_tools.h"

#include <softchain/fem/cell_conforming_polylines.h>

#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  double length(const SpringPolyline &line)
  {
    double sum = 0;
    const unsigned int n = line.points.size();
    for (unsigned int k = 0; k + 1 < n + (line.closed ? 1 : 0); ++k)
      sum += line.points[k].distance(line.points[(k + 1) % n]);
    return sum;
  }

  // Distance of p from the straight segment a-b.
  double distance_to_segment(const Point<3> &p, const Point<3> &a, const Point<3> &b)
  {
    const Tensor<1, 3> d = b - a;
    const double       t = std::clamp((p - a) * d / d.norm_square(), 0.0, 1.0);
    return p.distance(a + t * d);
  }
} // namespace

TEST_CASE("split spring polylines have every link in one cell", "[fem][springs]")
{
  // 4 x 2 x 2 hexahedra on [0, 4] x [0, 2] x [0, 2].
  Triangulation<3> mesh;
  GridGenerator::subdivided_hyper_rectangle(mesh, {4, 2, 2}, Point<3>(0, 0, 0), Point<3>(4, 2, 2));
  const MappingQ<3> mapping(1);

  // A line along x at generic (y, z) crosses exactly the 3 interior faces
  // x = 1, 2, 3; a slanted closed ring crosses faces in all three directions.
  const SpringPolyline straight{"fabric", {Point<3>(0.1, 0.3, 0.7), Point<3>(3.9, 0.3, 0.7)}, false};
  const SpringPolyline ring{"thread",
                            {Point<3>(0.2, 0.2, 0.2), Point<3>(3.7, 0.4, 0.3),
                             Point<3>(3.5, 1.8, 1.7), Point<3>(0.4, 1.5, 1.9)},
                            true};
  const auto split = cell_conforming_polylines({straight, ring}, mesh, mapping);
  REQUIRE(split.size() == 2);
  CHECK(split[0].points.size() == 2 + 3);
  CHECK(split[1].points.size() > ring.points.size() + 4);

  const GridTools::Cache<3> cache(mesh, mapping);
  for (unsigned int l = 0; l < 2; ++l)
    {
      const SpringPolyline &original = l == 0 ? straight : ring;
      const SpringPolyline &line     = split[l];
      CHECK(line.closed == original.closed);
      // Same fibre: same length, every new point on an original segment, the
      // original nodes kept in order (round-off 1e-12 of the unit-sized mesh).
      CHECK(std::abs(length(line) - length(original)) < 1e-12);
      unsigned int next_original = 0;
      const unsigned int n = original.points.size();
      for (const auto &p : line.points)
        {
          if (next_original < n && p.distance(original.points[next_original]) < 1e-14)
            ++next_original;
          else
            CHECK(distance_to_segment(p, original.points[next_original - 1],
                                      original.points[next_original % n]) < 1e-12);
        }
      CHECK(next_original == n);
      // Each link's ends lie in the cell around its midpoint; a crossing is
      // located to 1e-12, so the unit coordinates are inside to 1e-9.
      const unsigned int m = line.points.size();
      for (unsigned int k = 0; k + 1 < m + (line.closed ? 1 : 0); ++k)
        {
          const Point<3> a = line.points[k], b = line.points[(k + 1) % m];
          const auto cell = GridTools::find_active_cell_around_point(cache, a + 0.5 * (b - a)).first;
          for (const auto &end : {a, b})
            CHECK(cell->reference_cell().contains_point(
              mapping.transform_real_to_unit_cell(cell, end), 1e-9));
        }
    }
}

TEST_CASE("embedded springs add no coupling to the tangent's sparsity", "[fem][springs]")
{
  // On the built-in bender every spring link lies in one cell after the
  // split, so its stencil is a subset of that cell's DoFs: the pattern with
  // springs equals the pattern without them (an exact, integer check).
  for (const std::string element : {"Q1", "Q2"})
    {
      const auto with = [&](const bool springs) {
        test::SolverFixture f(test::parameters_from_text(
          "sparsity_springs", test::bender_prm(element, 4,
                                               std::string("subsection Springs\n  set Generate for bender = ") +
                                                 (springs ? "true" : "false") + "\nend\n")));
        REQUIRE((f.solver->spring_network() != nullptr) == springs);
        return f.solver->tangent().n_nonzero_elements();
      };
      INFO(element);
      CHECK(with(true) == with(false));
    }
}
