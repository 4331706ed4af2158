// AdaptiveLoadStepping on a model path whose Newton solves converge only in
// steps of at most 0.3 and take 4 iterations (of 12 allowed) when they do:
// the rules (grow by 1.5 after an easy step, a quarter after a failure,
// give up below the minimum step) followed exactly.
#include <softchain/fem/adaptive_load_stepping.h>

#include <catch2/catch.hpp>

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
  // 1 fails -> 0.25 converges -> 0.375 fails -> 0.09375 converges ->
  // 0.140625 converges -> 0.2109375 converges -> 0.31640625 fails -> ...:
  // every accepted step is at most 0.3, the last one lands on 1 exactly.
  REQUIRE(accepted.size() >= 2);
  CHECK(accepted[0] == 0.25);
  CHECK(accepted[1] == 0.25 + 0.09375);
  CHECK(accepted.back() == 1.0);
  for (std::size_t k = 1; k < accepted.size(); ++k)
    CHECK(accepted[k] - accepted[k - 1] <= 0.3 + 1e-12);
  CHECK(failures >= 2);
}

TEST_CASE("a failed step is retried a quarter as long, a hard step does not grow the next",
          "[fem][stepping]")
{
  const SolverParameters prm = stepping(1e-4, 1.0);
  AdaptiveLoadStepping   path(prm, 0.25);
  path.converged(4);
  CHECK(path.reached() == 0.25);
  CHECK(path.step() == 0.375); // grown by 1.5 after 4 of 12 iterations
  path.failed();
  CHECK(path.reached() == 0.25); // from the last converged state
  CHECK(path.next() == 0.25 + 0.375 / 4);
  path.converged(12); // a hard step: the step does not grow
  CHECK(path.step() == 0.375 / 4);
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
  CHECK(steps == 6); // 0.125, then 0.1875, then 0.2 per step: 0.3125, 0.5125, 0.7125, 0.9125, 1
}
