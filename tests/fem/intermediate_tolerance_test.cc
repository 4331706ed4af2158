// The load steps before a path's last converge only to Solver/Intermediate
// tolerance: their states are stepping stones. The state a solve ends in must
// be the one the final tolerances give, whatever the intermediate one, and
// the looser stepping stones must cost fewer Newton iterations where the
// springs make Newton converge linearly (the point of the setting).
#include "fem_test_tools.h"

#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

TEST_CASE("loose intermediate load steps end at the same equilibrium in fewer Newton iterations",
          "[fem][springs]")
{
  // The demo bender with its fabric and threads (Q2, 4 cells), 20 kPa from
  // rest: several load steps, Newton linear in the springs' active set.
  const auto prm = [](const std::string &tolerance) {
    return test::bender_prm("Q2", 4, "subsection Solver\n  set Intermediate tolerance = " + tolerance + "\nend\n");
  };
  LoadState target;
  target.pressure = 2e4;
  test::SolverFixture tight(test::parameters_from_text("intermediate_tight", prm("1e-6")));
  test::SolverFixture loose(test::parameters_from_text("intermediate_loose", prm("1e-2")));
  REQUIRE(loose.prm.solver.intermediate_tolerance == 1e-2);
  const auto a = tight.solver->solve(target), b = loose.solver->solve(target);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  REQUIRE(a.load_steps > 2);

  const auto tip = [](const test::SolverFixture &f) {
    return mean_boundary_displacement(f.solver->space(), f.solver->displacement(), boundary::tip);
  };
  // Both end converged to the final tolerances (1e-6 relative residual and
  // update) at the same equilibrium: 1e-5 relative bounds their distance
  // with a 10x margin (measured on P10 at 40 kPa: 3e-14 apart).
  INFO("tight " << tip(tight) << ", loose " << tip(loose));
  CHECK((tip(tight) - tip(loose)).norm() < 1e-5 * tip(tight).norm());
  // Measured here: fewer Newton iterations with the loose stepping stones.
  INFO("Newton iterations: tight " << a.newton_iterations << ", loose " << b.newton_iterations);
  CHECK(b.newton_iterations < a.newton_iterations);
}
