// Richardson extrapolation against values of the exact form
// f(h) = f* + C h^p, for which the procedure recovers f* and p exactly, up
// to round-off: the smallest differences f2 - f1 here are ~1e-7 of f
// (C = -40, p = 3.3), which double precision holds to ~1e-9 relative, so p
// and f* are checked to 1e-6 relative (of p and of the coarsest error). Any
// wrong sign, ratio or exponent in the formula misses by far more.
#include <softchain/data/richardson_extrapolation.h>

#include <catch2/catch.hpp>

#include <cmath>

using softchain::data::RichardsonExtrapolation;

TEST_CASE("Richardson extrapolation recovers the limit and order of f* + C h^p",
          "[data][richardson]")
{
  const std::array<double, 3> h{0.0025, 0.0033, 0.0048}; // unequal ratios, finest first
  for (const double p : {1.0, 2.0, 3.3})
    for (const double C : {-40.0, 5e3})
      {
        std::array<double, 3> f;
        for (int k = 0; k < 3; ++k)
          f[k] = 1.7 + C * std::pow(h[k], p);
        const auto r = RichardsonExtrapolation::of(h, f);
        INFO("p = " << p << ", C = " << C << ": value " << r.value << ", order " << r.order);
        CHECK(r.asymptotic);
        CHECK(r.order == Approx(p).epsilon(1e-6));
        CHECK(std::abs(r.value - 1.7) <= 1e-6 * std::abs(f[2] - 1.7));
        // The uncertainty is the GCI's: 1.25 times the finest value's error.
        CHECK(r.uncertainty == Approx(1.25 * std::abs(f[0] - 1.7)).epsilon(1e-6));
      }
}

// Outside the asymptotic range (oscillating values, or an order past 8) the
// finest value is the estimate, uncertain by its distance to the next.
TEST_CASE("Richardson extrapolation falls back on the finest value where it must",
          "[data][richardson]")
{
  const std::array<double, 3> h{1.0, 1.5, 2.25};
  const auto oscillating = RichardsonExtrapolation::of(h, {1.0, 1.2, 0.9});
  CHECK_FALSE(oscillating.asymptotic);
  CHECK(oscillating.value == 1.0);
  CHECK(oscillating.uncertainty == Approx(0.2));
  const auto too_fast = RichardsonExtrapolation::of(h, {1.0, 1.0001, 2.0});
  CHECK_FALSE(too_fast.asymptotic);
  CHECK(too_fast.value == 1.0);
  const auto converged = RichardsonExtrapolation::of(h, {3.0, 3.0, 3.0});
  CHECK(converged.value == 3.0);
  CHECK(converged.uncertainty == 0.0);
}
