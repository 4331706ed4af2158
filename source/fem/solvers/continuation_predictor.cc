#include <softchain/fem/continuation_predictor.h>

namespace softchain::fem
{
  using namespace dealii;

  ContinuationPredictor::ContinuationPredictor(const TrilinosWrappers::MPI::Vector &u, const double scalar)
    : states{{0.0, u, scalar}}
  {}

  void ContinuationPredictor::converged(const double s, const TrilinosWrappers::MPI::Vector &u,
                                        const double scalar)
  {
    if (states.size() == 4)
      states.pop_back();
    states.insert(states.begin(), {s, u, scalar});
    quadratic = false;
    if (states.size() < 4)
      return;
    // How far each order's prediction from the older states lands from u_0.
    TrilinosWrappers::MPI::Vector secant(u), parabola(u);
    extrapolate(1, 2, s, secant);
    extrapolate(1, 3, s, parabola);
    secant -= u;
    parabola -= u;
    quadratic = parabola.l2_norm() < secant.l2_norm();
  }

  bool ContinuationPredictor::predict(const double s, TrilinosWrappers::MPI::Vector &u,
                                      double *const scalar) const
  {
    if (states.size() < 2)
      return false;
    const double predicted = extrapolate(0, quadratic ? 3 : 2, s, u);
    if (scalar)
      *scalar = predicted;
    return true;
  }

  // u(s) = sum_i L_i(s) u_i, L_i(s) = prod_{j != i} (s - s_j) / (s_i - s_j).
  double ContinuationPredictor::extrapolate(const unsigned int first, const unsigned int n,
                                            const double s, TrilinosWrappers::MPI::Vector &u) const
  {
    u             = 0;
    double scalar = 0;
    for (unsigned int i = first; i < first + n; ++i)
      {
        double weight = 1.0;
        for (unsigned int j = first; j < first + n; ++j)
          if (j != i)
            weight *= (s - states[j].s) / (states[i].s - states[j].s);
        u.add(weight, states[i].u);
        scalar += weight * states[i].scalar;
      }
    return scalar;
  }
} // namespace softchain::fem
