// A solve continues from the state the last one ended in, with the springs'
// link tensions it ended with (EmbeddedSpringNetwork's Newton unknowns). Its
// answer must not depend on the path: to p in one solve, or to p/2 and then
// on to p, both end at the equilibrium of the tension law at p.
#include "fem_test_tools.h"

#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

TEST_CASE("a solve continued from a converged state ends at the equilibrium a direct solve reaches",
          "[fem][springs]")
{
  // The demo bender with its fabric and threads (Q2, 4 cells), 10 kPa.
  const std::string prm = test::bender_prm("Q2", 4);
  LoadState         full, half;
  full.pressure = 1e4;
  half.pressure = 5e3;

  test::SolverFixture direct(test::parameters_from_text("path_direct", prm));
  REQUIRE(direct.solver->solve(full).converged);
  test::SolverFixture twice(test::parameters_from_text("path_twice", prm));
  REQUIRE(twice.solver->solve(half).converged);
  REQUIRE(twice.solver->solve(full).converged);

  const auto tip = [](const test::SolverFixture &f) {
    return mean_boundary_displacement(f.solver->space(), f.solver->displacement(), boundary::tip);
  };
  const Tensor<1, 3> a = tip(direct), b = tip(twice);
  // Both are equilibria to the solver's tolerance (1e-6 relative residual
  // and update), so they agree to about that; 1e-5 leaves a margin of 10.
  // A solve that ended on stale link tensions (off the law) would miss by
  // the law's effect: the springs move this tip by tens of per cent.
  INFO("direct " << a << ", via half the pressure " << b);
  CHECK((a - b).norm() < 1e-5 * a.norm());
}
