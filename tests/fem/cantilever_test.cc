// A clamped solid cantilever (100 x 10 x 10 mm, E = 2.6e5 Pa) under a small
// dead shear traction on its tip face, against Timoshenko beam theory:
//     delta = F L^3 / (3 E I) + F L / (kappa G A),
// with Cowper's shear coefficient of a rectangular section,
// kappa = 10 (1 + nu) / (12 + 11 nu) (G. R. Cowper, J. Appl. Mech. 33 (1966)
// 335-340). The load gives delta / L ~ 1.5e-3, so geometric nonlinearity
// changes delta by ~(delta/L)^2 ~ 1e-6 relative: the finite-strain solver
// must reproduce the linear beam.
//
// Error budget, measured with Q2 on 10n x n x n cells, n = 1, 2, 4:
//  - discretisation: successive differences shrink by a factor r = 3.2
//    (nu = 0.3) and 2.5 (nu = 0.48, slower: near incompressibility and the
//    clamped edges' singularity), so the error left at n = 4 is about
//    (delta_4 - delta_2) / (r - 1): 0.07 % and 0.8 %. The test extrapolates
//    with the measured r and checks that r > 2 (convergence).
//  - model: the fully clamped root face cannot contract laterally (Poisson)
//    nor warp, unlike the beam's root; this stiffens a root zone of length
//    ~h and lowers delta by a relative amount ~ h / L (measured: extrapolated
//    -0.67 % at L/h = 10 and -0.34 % at L/h = 20 for nu = 0.3, -1.7 % and
//    -0.87 % for nu = 0.48). The tolerances are 1.5 times the L/h = 10 values.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>


#include <catch2/catch.hpp>

#include <cmath>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

// Its own namespace, so that the unity batch that compiles this file with
// others holds each file's constants once.
namespace cantilever_test
{

  namespace
  {
    constexpr double L = 0.1, h = 0.01; // length and square section edge [m]
    constexpr double E        = 2.6e5;  // the paper's silicone
    constexpr double traction = 1.0;    // N/m^2 along y: F = 1e-4 N

    double timoshenko_deflection(const double nu)
    {
      const double F = traction * h * h, I = h * h * h * h / 12, A = h * h;
      const double G = E / (2 * (1 + nu)), kappa = 10 * (1 + nu) / (12 + 11 * nu);
      return F * L * L * L / (3 * E * I) + F * L / (kappa * G * A);
    }

    // Mean tip-face deflection (the centroid's, in beam terms) of a Q2 mesh
    // with n cells across the section and 10 n along the length.
    double fem_deflection(const double nu, const unsigned int n)
    {
      Triangulation<3> mesh;
      test::cantilever_block(mesh, {10 * n, n, n}, L, h);
      test::MeshSolverFixture f(
        test::parameters_from_text("cantilever",
                                   test::solid_prm("Q2", "log", E, nu,
                                                   "subsection Solver\n  set Initial load step = 1\n"
                                                   "end\n")),
        mesh);
      LoadState load;
      load.tip_traction[1] = traction;
      REQUIRE(f.solver->solve(load).converged);
      return mean_boundary_displacement(f.solver->space(), f.solver->displacement(),
                                        boundary::tip)[1];
    }
  } // namespace

  TEST_CASE("cantilever tip deflection matches Timoshenko beam theory", "[fem][cantilever]")
  {
    for (const auto &[nu, model_tolerance] : {std::pair{0.3, 0.01}, std::pair{0.48, 0.025}})
      {
        const double beam = timoshenko_deflection(nu);
        double       delta[3];
        for (const unsigned int k : {0u, 1u, 2u})
          delta[k] = fem_deflection(nu, 1u << k);
        const double ratio    = (delta[1] - delta[0]) / (delta[2] - delta[1]);
        const double limit    = delta[2] + (delta[2] - delta[1]) / (ratio - 1);
        WARN("cantilever, nu = " << nu << ": Q2 delta = " << delta[0] << ", " << delta[1] << ", "
                                 << delta[2] << " m for n = 1, 2, 4; extrapolated " << limit
                                 << " m; Timoshenko " << beam << " m (relative difference "
                                 << limit / beam - 1 << ")");
        CHECK(ratio > 2);
        CHECK(limit == Approx(beam).epsilon(model_tolerance));
      }
  }
} // namespace cantilever_test
