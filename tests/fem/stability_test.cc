// Numerical-stability scenarios, each small enough for CI: every
// run must end converged or stopped with a named reason -- never NaN, a
// crash or a silent wrong state.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/cell_orientation.h>

#include <deal.II/grid/grid_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <tuple>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // The demo bender (Q1, 4 cells along x) with the given spring rigidities.
  test::SolverFixture bender(const double fabric_EA, const double thread_EA)
  {
    return test::SolverFixture(test::parameters_from_text(
      "stability", test::bender_prm("Q1", 4,
                                    "subsection Springs\n  set Axial rigidity = fabric: " +
                                      std::to_string(fabric_EA) + ", thread: " +
                                      std::to_string(thread_EA) + "\nend\n")));
  }

  double tip_uy(const QuasiStaticSolver &solver)
  {
    return mean_boundary_displacement(solver.space(), solver.displacement(), boundary::tip)[1];
  }
} // namespace

TEST_CASE("spring rigidity from 1e2 to 1e6 times the silicone's: converged, no Newton cycling",
          "[fem][stability]")
{
  // The silicone's axial rigidity over a wall cell: E h^2 = 2.6e5 Pa x
  // (2 mm)^2 ~ 1 N. The springs' EA from 1e2 to 1e6 N spans four decades
  // around the fabric's 2000 N; the tension-only law must not make Newton
  // cycle between slack and taut: each load step converges within the
  // iteration limit (12). Physically the fabric becomes inextensible: from
  // 1e4 N on the tip deflection saturates (measured -9.256, -9.213, -9.293
  // mm: within 0.9 %, so 1 % is asserted), and the soft 1e2 N fabric
  // stretches and bends the finger less (measured -8.12 mm). Cost: 12 Newton
  // iterations at 1e2 N, 25 at 1e6 N.
  std::map<double, double> uy_of;
  for (const double EA : {1e2, 1e3, 1e4, 1e5, 1e6})
    {
      auto      f = bender(EA, EA / 4);
      LoadState load;
      load.pressure     = 1e4;
      const auto result = f.solver->solve(load);
      INFO("EA = " << EA << " N: " << result.reason);
      REQUIRE(result.converged);
      CHECK(result.newton_iterations <= 12 * result.load_steps);
      const double uy = tip_uy(*f.solver);
      WARN("EA = " << EA << " N: tip u_y = " << uy << " m, " << result.load_steps
                   << " load steps, " << result.newton_iterations << " Newton iterations");
      CHECK(std::isfinite(uy));
      CHECK(uy < 0); // toward the fabric
      uy_of[EA] = uy;
    }
  for (const double EA : {1e4, 1e5})
    CHECK(std::abs(uy_of[EA] / uy_of[1e6] - 1) < 0.01);
  CHECK(uy_of[1e2] > 1.05 * uy_of[1e4]); // less bending (u_y < 0)
}

TEST_CASE("lateral tip forces up to 2 N: the solver follows or stops with a named reason",
          "[fem][stability]")
{
  // The paper saw the P10 buckle above 0.7 N; on the demo bender a 2 N
  // lateral (z) force at the tip is far past its linear range.
  auto         f = bender(2000, 500);
  const double L = 0.08, W = 0.018, H = 0.012;
  for (const double force : {0.5, 1.0, 2.0})
    {
      LoadState load;
      load.point_loads.push_back({Point<3>(L - 0.001, H / 2, W / 2), Tensor<1, 3>({0, 0, force})});
      const auto result = f.solver->solve(load);
      INFO(force << " N: " << result.reason);
      const double uz =
        mean_boundary_displacement(f.solver->space(), f.solver->displacement(), boundary::tip)[2];
      WARN("lateral " << force << " N: converged " << result.converged << ", load factor "
                      << result.load_factor_reached << ", tip u_z " << uz << " m "
                      << result.reason);
      CHECK(std::isfinite(uz));
      if (result.converged)
        CHECK(uz > 0);
      else
        CHECK(!result.reason.empty());
      f.solver->reset();
    }
}

namespace
{
  // Tip deflection of the 100 x 10 x 10 mm silicone block (Q2, 10 x 3 x 3
  // cells: 36 interior nodes) under a 0.02 N tip shear (delta / L ~ 0.27,
  // nonlinear), with its interior nodes jittered randomly by `jitter` of
  // their shortest edge (deal.II's seeded GridTools::distort_random).
  // Returns (converged, deflection, smallest scaled Jacobian).
  std::tuple<bool, double, double> jittered_block_deflection(const double jitter)
  {
    constexpr double L = 0.1, h = 0.01;
    Triangulation<3> mesh;
    test::cantilever_block(mesh, {10, 3, 3}, L, h);
    if (jitter > 0)
      GridTools::distort_random(jitter, mesh, true);
    check_cell_orientation(mesh, "jittered block");
    test::MeshSolverFixture f(test::parameters_from_text("jitter", test::solid_prm("Q2", "log", 2.6e5, 0.48)),
                              mesh);
    LoadState load;
    load.tip_traction[1] = 0.02 / (h * h);
    const auto result = f.solver->solve(load);
    INFO(result.reason);
    return {result.converged,
            mean_boundary_displacement(f.solver->space(), f.solver->displacement(), boundary::tip)[1],
            smallest_scaled_jacobian(mesh)};
  }
} // namespace

TEST_CASE("a mesh with 20 % random node jitter converges close to the regular mesh's answer",
          "[fem][stability]")
{
  const auto [regular_converged, regular, regular_quality]    = jittered_block_deflection(0.0);
  const auto [jittered_converged, jittered, jittered_quality] = jittered_block_deflection(0.2);
  WARN("0.02 N tip shear: tip deflection " << regular << " m regular, " << jittered
                                          << " m with 20 % node jitter (smallest scaled Jacobian "
                                          << regular_quality << " -> " << jittered_quality << ")");
  REQUIRE(regular_converged);
  REQUIRE(jittered_converged);
  CHECK(jittered_quality < 0.9 * regular_quality); // the jitter did distort the cells
  // Measured: 4.6e-4 relative (26.81 against 26.82 mm). Distortion moves the
  // answer by the order of the regular mesh's own discretisation error (Q2,
  // 3 cells across: ~1 %, cantilever_test.cc), so 0.5 % is asserted.
  CHECK(jittered == Approx(regular).epsilon(0.005));
}

TEST_CASE("Poisson's ratio from 0.45 to 0.4999: converged, and the linear hexahedra lock",
          "[fem][stability]")
{
  // The demo bender (Q1, 4 cells) at 10 kPa. As nu -> 1/2 the bulk modulus
  // grows 500x (kappa / mu = 2 (1 + nu) / (3 (1 - 2 nu)): 9.7 at 0.45,
  // 5e3 at 0.4999), the tangent's condition number with it; Newton must
  // still converge. Q1 locks volumetrically, so its deflection must fall
  // as nu grows (the quadratic elements' behaviour is benchmarks/poisson_sweep).
  double previous = -1.0;
  for (const double nu : {0.45, 0.48, 0.49, 0.499, 0.4999})
    {
      test::SolverFixture f(test::parameters_from_text(
        "poisson", test::bender_prm("Q1", 4,
                                    "subsection Materials\n  subsection silicone\n"
                                    "    set Poisson's ratio = " + std::to_string(nu) +
                                      "\n  end\nend\n")));
      LoadState load;
      load.pressure     = 1e4;
      const auto result = f.solver->solve(load);
      INFO("nu = " << nu << ": " << result.reason);
      REQUIRE(result.converged);
      const double deflection = -tip_uy(*f.solver);
      WARN("nu = " << nu << ": tip u_y = " << -deflection << " m, " << result.load_steps
                   << " load steps, " << result.newton_iterations << " Newton iterations");
      CHECK(deflection > 0);
      if (previous > 0)
        CHECK(deflection < previous);
      previous = deflection;
    }
}
