// AdaptiveLoadStepping on a model path whose Newton solves converge only in
// steps of at most 0.3 and take 4 iterations when they do: the rules (the
// next step scaled by sqrt(5 / I) within [1/2, 2] after a step of I
// iterations, a quarter after a failure, give up below the minimum step)
// followed exactly.
#include <softchain/fem/adaptive_load_stepping.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace softchain::fem;

namespace
{
  SolverParameters stepping(const double min_step, const double max_step)
  {
    SolverParameters prm{};
    prm.max_newton_iterations = 12;
    prm.min_load_step         = min_step;
    prm.max_load_step         = max_step;
    return prm;
  }
} // namespace

TEST_CASE("load steps grow after easy steps, are cut after failures and end at 1",
          "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-4, 1.0);
  AdaptiveLoadStepping   path(prm, 1.0);
  std::vector<double>    accepted;
  unsigned int           failures = 0;
  while (!path.finished())
    if (path.next() - path.reached() <= 0.3 + 1e-12)
      {
        path.converged(4);
        accepted.push_back(path.reached());
      }
    else
      {
        REQUIRE(path.failed());
        ++failures;
      }
  // 1 fails -> 0.25 converges -> 0.25 sqrt(5/4) = 0.2795 converges ->
  // 0.3125 fails -> 0.078 converges -> ...: every accepted step is at most
  // 0.3, the last one lands on 1 exactly.
  REQUIRE(accepted.size() >= 3);
  CHECK(accepted[0] == 0.25);
  CHECK(accepted[1] == Approx(0.25 + 0.25 * std::sqrt(1.25)).epsilon(1e-14));
  CHECK(accepted.back() == 1.0);
  for (std::size_t k = 1; k < accepted.size(); ++k)
    CHECK(accepted[k] - accepted[k - 1] <= 0.3 + 1e-12);
  CHECK(failures >= 2);
}

TEST_CASE("a failed step is retried a quarter as long, a hard step shrinks the next",
          "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-4, 1.0);
  AdaptiveLoadStepping   path(prm, 0.25);
  path.converged(5); // the desired count: the step stays
  CHECK(path.reached() == 0.25);
  CHECK(path.step() == 0.25);
  path.failed();
  CHECK(path.reached() == 0.25); // from the last converged state
  CHECK(path.next() == 0.25 + 0.25 / 4);
  path.converged(20); // a hard step: sqrt(5/20) = 1/2
  CHECK(path.step() == Approx(0.25 / 8).epsilon(1e-14));
  path.converged(80); // sqrt(5/80) = 1/4, kept at 1/2
  CHECK(path.step() == Approx(0.25 / 16).epsilon(1e-14));
  path.converged(1); // sqrt(5) = 2.24, kept at 2
  CHECK(path.step() == Approx(0.25 / 8).epsilon(1e-14));
}

TEST_CASE("a step that would leave a sliver of the path goes to its end, within the maximum step",
          "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-4, 1.0);
  AdaptiveLoadStepping   path(prm, 0.45);
  path.converged(5);
  CHECK(path.next() == 1.0); // 0.55 left, within 1.25 times the step 0.45
  AdaptiveLoadStepping short_path(prm, 0.4);
  short_path.converged(5);
  CHECK(short_path.next() == 0.8); // 0.6 left: more than 1.25 times 0.4
  const SolverParameters capped = stepping(1e-4, 0.5);
  AdaptiveLoadStepping   capped_path(capped, 0.45);
  capped_path.converged(5);
  CHECK(capped_path.next() == Approx(0.9).epsilon(1e-14)); // 0.55 left exceeds the maximum step
}

TEST_CASE("a path whose every step fails is given up below the minimum step",
          "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-3, 0.5);
  AdaptiveLoadStepping   path(prm, 0.125);
  unsigned int           cuts = 0;
  while (path.failed())
    ++cuts;
  // 0.125 / 4^k >= 1e-3 for k = 1, 2, 3 (0.03125, 0.0078, 0.00195); k = 4 gives 4.9e-4.
  CHECK(cuts == 3);
  CHECK(path.reached() == 0.0);
  CHECK_FALSE(path.finished());
}

TEST_CASE("load steps never grow beyond the maximum load step", "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-4, 0.2);
  AdaptiveLoadStepping   path(prm, 0.125);
  unsigned int           steps = 0;
  while (!path.finished())
    {
      const double before = path.reached();
      path.converged(1);
      CHECK(path.reached() - before <= 0.2 + 1e-12);
      ++steps;
    }
  CHECK(steps == 6); // 0.125, then 0.2 per step (2 x 0.125, kept at 0.2): 0.325, ..., 0.925, 1
}
