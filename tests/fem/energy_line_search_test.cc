// EnergyLineSearch on model energies whose minimum along the step is known
// in closed form: a hardening (Duffing) spring, on which the cubic model is
// exact; a quadratic energy, on which it is not; and a step whose
// minimiser lies where the state is inadmissible.
#include <softchain/fem/energy_line_search.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace softchain::fem;

TEST_CASE("The line search lands on the minimum of a hardening spring's energy in one trial",
          "[line_search]")
{
  // E(u) = k u^2/2 + c u^4/4 - F u, Newton's first step from u = 0 is
  // du = F/k, and along it s(a) = du R(a du) = s0 (1 - a) + c du^4 a^3 with
  // s0 = -F du: the model itself. Its zero solves k a du + c (a du)^3 = F.
  const double k = 2.0, c = 50.0, F = 3.0, du = F / k;
  const auto   slope = [&](const double a) { return du * (k * a * du + c * std::pow(a * du, 3) - F); };
  const auto   step  = EnergyLineSearch::minimise(slope(0), slope(1), slope);
  CHECK(step.evaluations == 1);
  // The equilibrium along du to round-off: Newton on the scalar model stops
  // at a relative change of 1e-12.
  const double u = step.fraction * du;
  CHECK(std::abs(k * u + c * u * u * u - F) <= 1e-10 * F);
  CHECK(step.fraction < 0.5); // far short of the linear step: the spring hardens
}

TEST_CASE("The cubic model's zero is exact where known", "[line_search]")
{
  // m(a) = s0 (1 - a) + s1 a^3 vanishes at a* for s1 = -s0 (1 - a*) / a*^3.
  for (const double a_star : {0.05, 0.25, 0.7, 0.999})
    {
      const double s0 = -3.0, s1 = -s0 * (1 - a_star) / std::pow(a_star, 3);
      CHECK(EnergyLineSearch::cubic_model_zero(s0, s1) == Approx(a_star).epsilon(1e-12));
    }
}

TEST_CASE("The line search meets its slope test on a quadratic energy", "[line_search]")
{
  // s linear with a zero at a = 0.1 (the cubic model puts it at 0.40): the
  // bracket's secant must find it within the trial budget.
  const double s0    = -1.0;
  const auto   slope = [&](const double a) { return s0 + 10.0 * a; };
  const auto   step  = EnergyLineSearch::minimise(s0, slope(1), slope);
  CHECK(step.evaluations >= 2); // the model's first trial fails the test
  CHECK(step.evaluations <= EnergyLineSearch::max_trials);
  CHECK(std::abs(slope(step.fraction)) <= EnergyLineSearch::accepted_slope * std::abs(s0));
}

TEST_CASE("The line search steps short of inadmissible states", "[line_search]")
{
  // The energy's minimum along the step (a = 1/3) lies where an element
  // would invert (a in (0.3, 0.99)); the step must stay admissible.
  const auto slope = [](const double a) {
    return a > 0.3 && a < 0.99 ? std::numeric_limits<double>::infinity() : -1.0 + 3.0 * a;
  };
  const auto step = EnergyLineSearch::minimise(-1.0, slope(1), slope);
  CHECK(step.fraction > 0.0);
  CHECK(std::isfinite(slope(step.fraction)));
  CHECK(std::abs(slope(step.fraction)) <= EnergyLineSearch::accepted_slope);
}

TEST_CASE("A full step short of the minimum is taken whole", "[line_search]")
{
  unsigned int calls = 0;
  const auto   step  = EnergyLineSearch::minimise(-1.0, -0.9, [&](double) { return ++calls, 0.0; });
  CHECK(step.fraction == 1.0);
  CHECK(calls == 0);
}
