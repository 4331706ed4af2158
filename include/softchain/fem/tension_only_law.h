#pragma once
// TensionOnlyLaw: the axial law of the paper's passive structures (Sec.
// III-A), a string that carries tension and no compression. In strain units
// (tension t = T/EA, strain eps = (l - L)/L) the ideal law is the
// complementarity
//     t >= 0,   g = t - eps >= 0,   t g = 0
// (taut: g = 0, t = eps; slack: t = 0, g = -eps). Its kink at eps = 0 is
// relaxed as an interior-point method relaxes complementarity, t g = delta^2/4,
// whose positive root is the hyperbola
//     t(eps) = (eps + sqrt(eps^2 + delta^2)) / 2,
// smooth, increasing, within delta/2 of the ideal law everywhere and within
// delta^2 / (4 |eps|) of it for |eps| >> delta (delta = Springs/Tension
// smoothing strain). Written in t and g, the relaxed law is bilinear, which
// lets Newton carry each link's tension as an unknown of its own
// (EmbeddedSpringNetwork): see the update below.
#include <cmath>

namespace softchain::fem
{
  class TensionOnlyLaw
  {
  public:
    explicit TensionOnlyLaw(double smoothing_strain)
      : delta(smoothing_strain)
    {}

    double smoothing_strain() const { return delta; }
    // The relaxed complementarity's right-hand side t g = m = delta^2 / 4.
    double complementarity() const { return delta * delta / 4; }

    // t(eps) and dt/deps = t / (t + g) of the relaxed law.
    double tension(double eps) const { return state_at(eps).tension; }
    double slope(double eps) const { return state_at(eps).tension / std::hypot(eps, delta); }

    // A link's own unknowns: tension t and gap g, both positive.
    struct State
    {
      double tension;
      double gap;
    };
    // On the law at strain eps (its residuals vanish). With h = sqrt(eps^2 +
    // delta^2), t = (h + eps)/2 and g = (h - eps)/2; the smaller of the two
    // is computed as m over the larger, without cancellation (a slack link
    // at eps = -1e-2 has t = 2.5e-9 for delta = 1e-5, below the round-off
    // of h + eps).
    State state_at(double eps) const
    {
      const double h = std::hypot(eps, delta);
      if (eps >= 0)
        {
          const double t = (h + eps) / 2;
          return {t, complementarity() / t};
        }
      const double g = (h - eps) / 2;
      return {complementarity() / g, g};
    }

    // Where a link at its rest length (eps = 0, the knee's centre) starts:
    // on the taut side of the knee, t = 10 delta and g = delta/40. Still
    // t g = m, but off g - t + eps = 0: its condensed tension is
    // 2 t g/(t + g) = 0.05 delta (the law's is delta/2) and its condensed
    // slope t/(t + g) = 0.9975 (the law's is 1/2). The paper's fabric and
    // threads are stress-free in the reference state, so at rest every link
    // sits at the knee; with the law's half slope the first linear step
    // from rest saw half-stiff strings and overshot until an element
    // inverted (P10 and the demo bender both failed their first load step,
    // 0.125 of the load, from rest). From this start the first step sees
    // the strings' stiffness, and a link the load compresses crosses the
    // knee in its first update, onto the law at its linearised strain.
    State rest_start() const { return {taut_start * delta, delta / (4 * taut_start)}; }

    // Newton's increment of (t, g) for a strain increment d_eps, from the
    // linearised equations  g - t + eps = 0  and  t g - m = 0:
    //     dt = (t (d_eps + r) - c) / (t + g),   dg = dt - d_eps - r,
    // with r = g - t + eps and c = t g - m. Where that step would take t or g
    // below a hundredth of its value (the link crosses the knee, from taut to
    // slack or back, where the linearised t g is poor), the link goes onto
    // the law at the linearised strain eps + d_eps instead: it stays inside
    // t, g > 0, as interior-point methods keep their iterates, and arrives
    // where its strain puts it rather than a fixed fraction of the way
    // (docs/history.md, "Link tensions as Newton unknowns").
    State increment(const State &s, double eps, double d_eps) const
    {
      const double r  = s.gap - s.tension + eps;
      const double c  = s.tension * s.gap - complementarity();
      const double dt = (s.tension * (d_eps + r) - c) / (s.tension + s.gap);
      const double dg = dt - d_eps - r;
      if (s.tension + dt < boundary_fraction * s.tension || s.gap + dg < boundary_fraction * s.gap)
        {
          const State on_law = state_at(eps + d_eps);
          return {on_law.tension - s.tension, on_law.gap - s.gap};
        }
      return {dt, dg};
    }

    // The tension Newton's next iterate balances once the local equations
    // are condensed: dt eliminated with d_eps = 0,
    //     t_eff = t + (t (eps - t) + m) / (t + g),
    // and its derivative dt_eff/deps = t / (t + g). On the law (r = c = 0)
    // t_eff = t(eps) and the derivative is slope(eps).
    double condensed_tension(const State &s, double eps) const
    {
      return s.tension + (s.tension * (eps - s.tension) + complementarity()) / (s.tension + s.gap);
    }
    double condensed_slope(const State &s) const { return s.tension / (s.tension + s.gap); }

  private:
    static constexpr double boundary_fraction = 0.01;
    static constexpr double taut_start        = 10;
    double                  delta;
  };
} // namespace softchain::fem
