// Cook's membrane against the deal.II code gallery, "Quasi-static
// finite-strain compressible elasticity" (J.-P. V. Pelteret, A. McBride,
// doi:10.5281/zenodo.1228964), README since 2021: the tapered plate with
// corners (0,0), (48,44), (48,60), (0,44) mm, 1 mm thick, clamped at x = 0,
// a dead shear traction on the 16 mm face at x = 48 mm totalling 1 N, u_z = 0
// on both flat faces (plane strain), one element through the thickness; the
// split neo-Hookean energy W = mu/2 (I1bar - 3) + kappa/4 (J^2 - 1 - 2 ln J)
// with mu = 422.5 kPa, nu = 0.3. The reference is the vertical displacement
// of the midpoint (48, 52) mm of the traction face, in mm.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_ids.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace cook_membrane_test
{

  namespace
  {
    constexpr double mm = 1e-3;
    constexpr double mu = 422.5e3, nu = 0.3;
    constexpr double thickness = 1 * mm;
    // 1 N over the 16 mm x 1 mm reference face.
    constexpr double traction = 1.0 / (16 * mm * thickness);

    // Boundary id of a face of the rectangle [0,48] x [0,44] x [-t/2, t/2] mm
    // with centre c: clamped left edge, loaded right edge, plane-strain faces.
    types::boundary_id cook_boundary_id(const Point<3> &c)
    {
      if (c[0] < 1e-6 * mm)
        return boundary::base;
      if (c[0] > 48 * mm - 1e-6 * mm)
        return boundary::tip;
      if (std::abs(std::abs(c[2]) - thickness / 2) < 1e-6 * mm)
        return boundary::fixed_z;
      return boundary::other;
    }

    // N x N x 1 cells on the trapezoid: the rectangle mapped by the bilinear
    // y -> y + (x / 48) (44 - 28 y / 44) (mm), which the trilinear cells
    // represent exactly.
    void cook_mesh(const unsigned int n, Triangulation<3> &mesh)
    {
      GridGenerator::subdivided_hyper_rectangle(mesh, {n, n, 1},
                                                Point<3>(0, 0, -thickness / 2),
                                                Point<3>(48 * mm, 44 * mm, thickness / 2));
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(cook_boundary_id(face->center()));
      GridTools::transform(
        [](const Point<3> &p) {
          const double s = p[0] / (48 * mm);
          return Point<3>(p[0], p[1] + s * (44 * mm - 28.0 / 44.0 * p[1]), p[2]);
        },
        mesh);
    }

    // `prm_name` names the .prm file, one per test case (safe under ctest -j).
    std::unique_ptr<test::MeshSolverFixture> cook_solver(const std::string &prm_name,
                                                         const std::string &element,
                                                         const unsigned int n,
                                                         const std::string &solver_options = "")
    {
      Triangulation<3> mesh;
      cook_mesh(n, mesh);
      return std::make_unique<test::MeshSolverFixture>(
        test::parameters_from_text(prm_name,
                                   test::solid_prm(element, "split", 2 * mu * (1 + nu), nu,
                                                   solver_options)),
        mesh);
    }

    LoadState cook_load()
    {
      LoadState load;
      load.tip_traction[1] = traction;
      return load;
    }

    // Vertical displacement [mm] of the traction face's midpoint.
    double midpoint_displacement(const std::string &element, const unsigned int n)
    {
      auto       f      = cook_solver("cook_" + element, element, n);
      const auto result = f->solver->solve(cook_load());
      REQUIRE(result.converged);
      return test::displacement_at(*f->solver, Point<3>(48 * mm, 52 * mm, 0))[1] / mm;
    }

    // Half a unit of the last printed digit of `printed` ("8.638" -> 5e-4).
    double half_last_digit(const std::string &printed)
    {
      const auto decimals = printed.size() - printed.find('.') - 1;
      return 0.5 * std::pow(10.0, -double(decimals));
    }

    void check_against_gallery(const std::string                                  &element,
                               const std::vector<std::pair<unsigned int, std::string>> &table)
    {
      for (const auto &[n, printed] : table)
        {
          const double u = midpoint_displacement(element, n);
          WARN("Cook's membrane " << element << ", " << n << " elements per edge: "
                                  << std::setprecision(6) << u << " mm (gallery " << printed
                                  << ")");
          // Newton stops at |R| <= 1e-8 |f_ext|, i.e. a displacement error ~1e-8
          // relative, far below the printed rounding: the gallery's digits
          // themselves are the tolerance.
          CHECK(std::abs(u - std::stod(printed)) <= half_last_digit(printed));
        }
    }
  } // namespace

  TEST_CASE("Cook's membrane Q1 matches the deal.II code gallery", "[fem][cook]")
  {
    check_against_gallery("Q1",
                          {{2, "8.638"}, {4, "12.07"}, {8, "13.86"}, {16, "14.49"}, {32, "14.67"}});
  }

  TEST_CASE("Cook's membrane Q2 matches the deal.II code gallery", "[fem][cook]")
  {
    check_against_gallery("Q2", {{2, "14.30"}, {4, "14.65"}, {8, "14.71"}, {16, "14.73"}});
  }

  // Newton with the exact tangent converges quadratically near the solution:
  // with e_k = |R_k| / |R_0|, e_{k+1} <= C e_k^2 (Kelley, Iterative Methods for
  // Linear and Nonlinear Equations, SIAM 1995, Thm. 5.1.2). Cook's membrane in
  // one load step (a 14 mm deflection of a 48 mm plate) needs ~9 iterations.
  // Measured C = e_{k+1} / e_k^2 over the last steps: 0.02 to 2 (with and without
  // the line search); C = 10 leaves a margin of 5. A linearly converging
  // iteration (a tangent term missing or wrong) gives e_{k+1} ~ rho e_k and
  // fails once e_k < rho / 10. Steps ending at the round-off floor (measured
  // 7e-13 |R_0|; 1e-11 |R_0| here) show no rate and are left out.
  TEST_CASE("Newton converges quadratically (Cook's membrane in one step)", "[fem][newton]")
  {
    auto f = cook_solver("cook_newton", "Q2", 4,
                         "subsection Solver\n  set Initial load step = 1\n"
                         "  set Residual tolerance = 1e-12\n  set Displacement tolerance = 1e-12\n"
                         "  set Maximum Newton iterations = 20\nend\n");
    const auto result = f->solver->solve(cook_load());
    REQUIRE(result.converged);
    REQUIRE(result.load_steps == 1);
    std::vector<double> e;
    std::ostringstream  sequence;
    for (const double r : result.residual_history)
      {
        e.push_back(r / result.residual_history.front());
        sequence << std::scientific << std::setprecision(3) << r << ' ';
      }
    WARN("Newton residuals |R_k| [N]: " << sequence.str());
    unsigned int checked = 0;
    for (std::size_t k = e.size() - 1; k-- > 0 && checked < 2;)
      if (e[k + 1] > 1e-11)
        {
          INFO("step " << k << ": e_k = " << e[k] << ", e_k+1 = " << e[k + 1]);
          CHECK(e[k + 1] <= 10 * e[k] * e[k]);
          ++checked;
        }
    CHECK(checked == 2);
  }
} // namespace cook_membrane_test
