// TensionOnlyLaw against its definition and Newton's theory: the relaxed
// complementarity t g = delta^2/4 with g = t - eps, its distance to the ideal
// law max(eps, 0), its slope against central differences, and the local
// Newton step on (t, g): quadratic convergence onto the law at a fixed strain,
// the condensed tension as the tension of that step, and a step across the
// knee landing on the law; the taut start of a link at rest.
#include <softchain/fem/tension_only_law.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using softchain::fem::TensionOnlyLaw;

namespace
{
  constexpr double delta = 1e-4;
  const double     strains[] = {-1e-2, -1e-3, -1e-4, -1e-5, 0.0, 1e-5, 1e-4, 1e-3, 1e-2};
} // namespace

TEST_CASE("the relaxed tension-only law is the positive root of t (t - eps) = delta^2/4",
          "[fem][springs]")
{
  const TensionOnlyLaw law(delta);
  CHECK(law.tension(0.0) == Approx(delta / 2).epsilon(1e-14));
  for (const double eps : strains)
    {
      INFO("eps " << eps);
      const double t = law.tension(eps);
      CHECK(t > 0);
      CHECK(t - eps > 0); // the gap: the link is never shorter than slack allows
      // Relative to the product's own scale t^2 + m: round-off 1e-16.
      CHECK(std::abs(t * (t - eps) - delta * delta / 4) <= 1e-14 * (t * t + delta * delta / 4));
      // Within delta/2 of the ideal law, and within delta^2 / (4 |eps|) of
      // it far from the knee (the positive root lies between the two).
      const double ideal = std::max(eps, 0.0);
      CHECK(t - ideal <= delta / 2 * (1 + 1e-12));
      if (std::abs(eps) > delta)
        CHECK(t - ideal <= delta * delta / (4 * std::abs(eps)) * (1 + 1e-12));
      // Slope against central differences with a step h = delta/1000:
      // truncation (h/delta)^2 ~ 1e-6 relative.
      const double h = delta * 1e-3;
      CHECK(law.slope(eps) == Approx((law.tension(eps + h) - law.tension(eps - h)) / (2 * h)).epsilon(1e-5));
      // The state's gap is t - eps, and t g = m to round-off of each.
      const auto s = law.state_at(eps);
      CHECK(s.tension == t);
      CHECK(std::abs(s.gap - s.tension + eps) <= 1e-15 * (s.tension + s.gap));
      CHECK(s.tension * s.gap == Approx(delta * delta / 4).epsilon(1e-14));
    }
}

// At a fixed strain the local equations g - t + eps = 0, t g = m are two
// smooth equations in (t, g): Newton from a state off the law converges to
// it quadratically (Kelley, Iterative Methods for Linear and Nonlinear
// Equations, Thm. 5.1.2). With e_k the distance to the law's tension,
// e_{k+1} <= C e_k^2 / t* with C = 1 (the product's second derivative is 1
// and the Jacobian's inverse is at most 1/(t + g) <= 1/t*), a margin of 10
// over the bound: a linear rate fails once e_k / t* < 1/10.
TEST_CASE("a link's Newton step converges quadratically onto its law at a fixed strain",
          "[fem][springs]")
{
  const TensionOnlyLaw law(delta);
  for (const double eps : {-1e-3, 0.0, 1e-3})
    {
      const auto            on_law = law.state_at(eps);
      const double          t_law = on_law.tension, scale = on_law.tension + on_law.gap;
      TensionOnlyLaw::State s{1.5 * t_law, 1.5 * on_law.gap};
      double                e = std::abs(s.tension - t_law);
      // Round-off: 1e-16 of the larger of t and g; the floor 1e-14 of it
      // leaves a margin of 100.
      for (int k = 0; k < 8 && e > 1e-14 * scale; ++k)
        {
          const auto step = law.increment(s, eps, 0.0);
          s               = {s.tension + step.tension, s.gap + step.gap};
          const double next = std::abs(s.tension - t_law);
          INFO("eps " << eps << ", iteration " << k << ": error " << e << " -> " << next);
          CHECK(next <= 10 * e * e / t_law + 1e-14 * scale);
          e = next;
        }
      CHECK(e <= 1e-14 * scale);
      CHECK(s.gap == Approx(on_law.gap).epsilon(1e-12));
    }
}

// The condensed tension is the tension of the local Newton step at the
// strain the displacement reaches (d_eps = 0 there), and its slope the
// derivative of the step's tension with respect to the strain increment.
TEST_CASE("the condensed tension and slope are those of the link's Newton step",
          "[fem][springs]")
{
  const TensionOnlyLaw        law(delta);
  const TensionOnlyLaw::State s{2e-4, 3e-5}; // off the law at every strain below
  for (const double eps : {-2e-5, 1e-5, 1.5e-4})
    {
      INFO("eps " << eps);
      const auto step = law.increment(s, eps, 0.0);
      REQUIRE(s.tension + step.tension > 0.01 * s.tension); // not across the knee
      CHECK(law.condensed_tension(s, eps) == Approx(s.tension + step.tension).epsilon(1e-12));
      const double h = 1e-9; // the step is linear in d_eps: exact up to round-off
      const double dt_deps =
        (law.increment(s, eps, h).tension - law.increment(s, eps, -h).tension) / (2 * h);
      CHECK(law.condensed_slope(s) == Approx(dt_deps).epsilon(1e-6));
    }
}

// A taut link whose strain increment makes it slack (and a slack one made
// taut) would leave t > 0 or g > 0 in one linearised step: it lands on the
// law at its linearised new strain instead.
TEST_CASE("a link's Newton step across the knee lands on the law at the new strain",
          "[fem][springs]")
{
  const TensionOnlyLaw law(delta);
  for (const auto &[eps, d_eps] : {std::pair{1e-3, -2e-3}, std::pair{-1e-3, 2e-3}})
    {
      INFO("eps " << eps << " + " << d_eps);
      const auto s    = law.state_at(eps);
      const auto step = law.increment(s, eps, d_eps);
      const auto to   = law.state_at(eps + d_eps);
      CHECK(s.tension + step.tension == Approx(to.tension).epsilon(1e-12));
      CHECK(s.gap + step.gap == Approx(to.gap).epsilon(1e-12));
    }
}

TEST_CASE("a link at rest starts on the taut side of the knee, with nearly its full slope",
          "[fem][springs]")
{
  const TensionOnlyLaw law(delta);
  const auto           s = law.rest_start();
  // Inside the relaxed complementarity (t g = m, both positive) but off the
  // law at eps = 0 (t - g = 0 there): the taut side, t > g.
  CHECK(s.tension > 0);
  CHECK(s.gap > 0);
  CHECK(s.tension * s.gap == Approx(law.complementarity()).epsilon(1e-14));
  CHECK(s.tension > 100 * s.gap);
  // Condensed at eps = 0: a tension below the law's delta/2 (the start adds
  // no spurious pull to the finger at rest) and a slope within 1 % of the
  // taut string's 1, where the law's is 1/2.
  CHECK(law.condensed_tension(s, 0.0) >= 0);
  CHECK(law.condensed_tension(s, 0.0) < 0.2 * law.tension(0.0));
  CHECK(law.condensed_slope(s) > 0.99);
  CHECK(law.slope(0.0) == Approx(0.5).epsilon(1e-14));
  // One local Newton step at eps = 0 brings it onto the law there.
  const auto step = law.increment(s, 0.0, 0.0);
  CHECK(s.tension + step.tension == Approx(law.tension(0.0)).epsilon(1e-6));
}
