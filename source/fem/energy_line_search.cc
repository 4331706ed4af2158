#include <softchain/fem/energy_line_search.h>

#include <cmath>

namespace softchain::fem
{
  // m(a) = s1 a^3 - s0 a + s0 rises monotonically from s0 < 0 at a = 0 to
  // s1 > 0 at a = 1 and is convex for a > 0, so Newton's iteration from
  // a = 1 descends monotonically onto its zero.
  double EnergyLineSearch::cubic_model_zero(const double s0, const double s1)
  {
    double a = 1.0;
    for (unsigned int k = 0; k < 60; ++k)
      {
        const double next = a - (s1 * a * a * a - s0 * a + s0) / (3 * s1 * a * a - s0);
        if (std::abs(next - a) <= 1e-12 * a)
          return next;
        a = next;
      }
    return a;
  }

  EnergyLineSearch::Step EnergyLineSearch::minimise(const double s0, const double s1, const Slope &slope)
  {
    struct Trial
    {
      double a, s;
    };
    if (s1 <= 0.0)
      return {1.0, 0};
    Trial        lo{0.0, s0}, hi{1.0, s1}, best{1.0, s1};
    int          side = 0; // which end the last trial replaced: -1 lo, +1 hi
    double       a    = cubic_model_zero(s0, s1);
    unsigned int k    = 0;
    while (k < max_trials)
      {
        const Trial trial{a, slope(a)};
        ++k;
        if (std::abs(trial.s) < std::abs(best.s))
          best = trial;
        if (std::abs(trial.s) <= accepted_slope * std::abs(s0))
          break;
        // Illinois: an end kept twice in a row has its s halved, so that
        // the next secant moves it.
        if (trial.s < 0.0)
          {
            lo = trial;
            hi.s /= side == -1 ? 2.0 : 1.0;
            side = -1;
          }
        else
          {
            hi = trial;
            lo.s /= side == 1 ? 2.0 : 1.0;
            side = 1;
          }
        a = std::isfinite(hi.s) ? (lo.a * hi.s - hi.a * lo.s) / (hi.s - lo.s) : (lo.a + hi.a) / 2;
      }
    return {best.a, k};
  }
} // namespace softchain::fem
