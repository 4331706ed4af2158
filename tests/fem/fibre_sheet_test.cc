// Fibre sheets: the quadrature that follows the mesh (sheet_quadrature) and
// the sheet's links in EmbeddedSpringNetwork, against closed forms.
#include "fem_test_tools.h"

#include <softchain/fem/base_reaction.h>
#include <softchain/fem/sheet_quadrature.h>

#include <deal.II/grid/grid_generator.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace fibre_sheet_test
{

  namespace
  {
    constexpr double L = 0.1, h = 0.01;

    // sum w_q and sum w_q x_q of the rule, x_q the quadrature points mapped back.
    std::pair<double, Point<3>> area_and_moment(const FiniteElementSpace    &space,
                                                const std::vector<Point<3>> &corners)
    {
      double   area = 0;
      Point<3> moment;
      for (const auto &rule : sheet_quadrature(space, corners))
        for (unsigned int q = 0; q < rule.weights.size(); ++q)
          {
            area += rule.weights[q];
            moment += rule.weights[q] *
                      space.mapping->transform_unit_to_real_cell(rule.cell, rule.unit_points[q]);
          }
      return {area, moment};
    }
  } // namespace

  // A parallelogram's area is |e1 x e2| and its first moment the area times its
  // centre (the corners' mean): both integrands are polynomials the rule
  // integrates exactly, so any cell clipped wrongly, counted twice or missed
  // shows at once; 1e-12 is round-off. The three sheets: one tilted across
  // cells, one in the plane of interior faces (y = h/2 with two cells across
  // the height: kept once, on the side of its normal), one on the boundary
  // (y = 0, where no neighbour takes it).
  TEST_CASE("a sheet's quadrature integrates its area and first moment exactly, once",
            "[fem][springs][sheets]")
  {
    for (const bool tetrahedra : {false, true})
      {
        Triangulation<3> box, mesh;
        test::cantilever_block(box, {7, 2, 3}, L, h);
        if (tetrahedra)
          GridGenerator::convert_hypercube_to_simplex_mesh(box, mesh);
        else
          mesh.copy_triangulation(box);
        const FiniteElementSpace space(mesh, tetrahedra ? ElementType::P2 : ElementType::Q2,
                                       MPI_COMM_WORLD);
        const std::vector<std::vector<Point<3>>> sheets{
          {{0.013, 0.001, 0.002}, {0.081, 0.004, 0.0015}, {0.084, 0.0095, 0.0085}, {0.016, 0.0065, 0.009}},
          {{0.01, h / 2, 0.001}, {0.09, h / 2, 0.001}, {0.09, h / 2, 0.009}, {0.01, h / 2, 0.001 + 0.008}},
          {{0.01, 0, 0.001}, {0.01, 0, 0.009}, {0.09, 0, 0.009}, {0.09, 0, 0.001}}};
        for (const auto &c : sheets)
          {
            const double area = cross_product_3d(c[1] - c[0], c[3] - c[0]).norm();
            const Point<3> centre = (c[0] + c[1] + c[2] + c[3]) / 4;
            const auto [integrated, moment] = area_and_moment(space, c);
            INFO((tetrahedra ? "tetrahedra" : "hexahedra") << ", sheet from " << c[0] << ": area "
                                                            << integrated << " (exact " << area << ")");
            CHECK(std::abs(integrated - area) <= 1e-12 * area);
            CHECK((moment - area * centre).norm() <= 1e-12 * area * L);
          }
      }
  }

  namespace
  {
    constexpr double E = 2.6e5, EA = 50.0, spacing = 0.002, d = 1e-3;

    // Base reaction along x after moving the tip face of a block of `cells`
    // by delta along x, with a sheet of x fibres in the plane y = h/2 over the
    // whole block (or none).
    double pull_sheet(const double delta, const bool with_sheet, const std::vector<unsigned int> &cells)
    {
      Triangulation<3> mesh;
      test::cantilever_block(mesh, cells, L, h);
      const Parameters prm = test::parameters_from_text(
        "sheet_block", test::solid_prm("Q2", "log", E, 0.0,
                                       "subsection Springs\n  set Axial rigidity = fabric: 50\n"
                                       "  set Tension smoothing strain = 0.001\nend\n"));
      std::vector<FibreSheet> sheets;
      if (with_sheet)
        sheets.push_back({"fabric",
                          {Point<3>(0, h / 2, 0), Point<3>(L, h / 2, 0), Point<3>(L, h / 2, h),
                           Point<3>(0, h / 2, h)},
                          {{Tensor<1, 3>({1, 0, 0}), spacing}}});
      std::ostringstream log;
      QuasiStaticSolver  solver(prm, mesh, {"solid"}, {}, sheets, MPI_COMM_WORLD, log);
      LoadState          target;
      target.tip_motion = TipMotion{Tensor<1, 3>({delta, 0, 0}), Tensor<1, 3>()};
      REQUIRE(solver.solve(target).converged);
      return BaseReaction(solver.space()).wrench(solver.support_forces()).force[0];
    }
  } // namespace

  // The block of embedded_spring_test.cc (nu = 0: a homogeneous stretch
  // lambda = 1 + eps with no lateral contraction) with a sheet of fibres along
  // x, EA every `spacing`, across its whole width h: the sheet's membrane
  // tension per unit width is (EA / spacing) t(eps), t the tension-only law,
  // so it adds (EA / spacing) h t(eps) to the base reaction. The sheet lies
  // inside the middle cells (3 cells across the height) or in the plane of
  // interior faces (2 cells), where it must count once. Tolerance 1e-6
  // relative, as for the spring (the Newton tolerance lies below; a sheet
  // counted twice, missed or compressive lies far above).
  TEST_CASE("a sheet pulled along its fibres adds its membrane tension to the reaction",
            "[fem][springs][sheets]")
  {
    for (const std::vector<unsigned int> &cells : {std::vector<unsigned int>{10, 3, 3},
                                                  std::vector<unsigned int>{10, 2, 3}})
      for (const double eps : {1e-2, 0.5 * d, -1e-2}) // taut, at the knee, slack
        {
          const double tension = EA / spacing * h * (eps + std::sqrt(eps * eps + d * d)) / 2;
          const double with = pull_sheet(eps * L, true, cells), without = pull_sheet(eps * L, false, cells);
          INFO(cells[1] << " cells across, strain " << eps << ": reaction with " << with
                        << " N, without " << without << " N, sheet law " << tension << " N");
          CHECK(std::abs((with - without) - tension) <= 1e-6 * std::max(tension, std::abs(without)));
        }
  }

  // The sheet's links in the tangent: K v against the central difference of
  // the residual at a random deformed state of a block with a tilted sheet
  // (two fibre families, smoothing strain 1e-3 so that the random state puts
  // quadrature points on every branch of the law, as the springs' tangent test
  // does). Step and bound as there: truncation and round-off ~1e-9, bound 1e-6.
  TEST_CASE("a sheet's tangent matches finite differences", "[fem][springs][sheets][tangent]")
  {
    Triangulation<3> mesh;
    test::cantilever_block(mesh, {6, 2, 2}, L, h);
    const Parameters prm = test::parameters_from_text(
      "sheet_tangent", test::solid_prm("Q2", "log", E, 0.45,
                                       "subsection Springs\n  set Axial rigidity = fabric: 50\n"
                                       "  set Tension smoothing strain = 0.001\nend\n"));
    const std::vector<Point<3>> c{Point<3>(0.005, 0.002, 0.001), Point<3>(0.095, 0.004, 0.001),
                                  Point<3>(0.095, 0.007, 0.009), Point<3>(0.005, 0.005, 0.009)};
    const std::vector<FibreSheet> sheets{
      {"fabric", c, {{(c[1] - c[0]) / (c[1] - c[0]).norm(), spacing}, {(c[3] - c[0]) / (c[3] - c[0]).norm(), spacing}}}};
    std::ostringstream log;
    QuasiStaticSolver  solver(prm, mesh, {"solid"}, {}, sheets, MPI_COMM_WORLD, log);
    const auto         u = test::smooth_displacement(solver, 2e-3, 0.05, 1);
    const auto         v = test::smooth_displacement(solver, 1.0, 1.0, 2);
    auto [Kv, fd]        = test::tangent_and_difference(solver, LoadState(), u, v, 1e-8);
    fd -= Kv;
    INFO("|K v| = " << Kv.l2_norm() << ", |K v - FD| = " << fd.l2_norm());
    CHECK(fd.l2_norm() <= 1e-6 * Kv.l2_norm());
  }
} // namespace fibre_sheet_test
