#pragma once
// EnergyLineSearch: how far to go along a Newton step du, from the slope of
// the energy along it, s(a) = du . R(u_old + a du) (Crisfield, Non-linear
// Finite Element Analysis of Solids and Structures, Vol. 1, Sec. 9.3).
// Newton's own linear model is s(a) = s0 (1 - a), with s0 = -du.K du < 0,
// so s'(0) = -s0. Where the full step overshoots (s(1) > 0), the step goes
// near the zero of s in (0, 1), where the energy along du is least.
//
// The first trial is the zero of the model
//     m(a) = s0 (1 - a) + s(1) a^3,
// which matches s(0), s'(0) and s(1), and whose slope grows with the cube
// of the step as that of a ballooning wall's membrane energy does (quartic
// in the deflection). Crisfield's secant (s linear in a) went a tenth of
// the way where s vanished at a quarter, three times in a row, on a bender
// from rest (docs/results.md, "A line search for stiffening walls"). Then
// regula falsi (Illinois variant) on the bracket, until |s(a)| <= 0.5 |s0|
// or after four trials; a trial whose state is inadmissible (an element
// inverted: s = +infinity) bounds the bracket from above and is bisected.
#include <functional>

namespace softchain::fem
{
  class EnergyLineSearch
  {
  public:
    // s(a) at a state along the step; +infinity where that state is
    // inadmissible.
    using Slope = std::function<double(double a)>;

    struct Step
    {
      double       fraction;    // of the Newton step, in (0, 1]
      unsigned int evaluations; // of s
    };

    // The step for s(0) = s0 < 0 and s(1) = s1 > 0 (the full step
    // overshoots); with s1 <= 0 the least energy lies beyond the full step,
    // which is then taken as it is (fraction 1, no evaluation).
    static Step minimise(double s0, double s1, const Slope &slope);

    // The zero in (0, 1) of the model m above, for s0 < 0 < s1.
    static double cubic_model_zero(double s0, double s1);

    static constexpr double       accepted_slope = 0.5; // |s(a)| <= this |s0|
    static constexpr unsigned int max_trials     = 4;
  };
} // namespace softchain::fem
