#include <softchain/fem/adaptive_load_stepping.h>

#include <algorithm>

namespace softchain::fem
{
  AdaptiveLoadStepping::AdaptiveLoadStepping(const SolverParameters &prm, const double first_step)
    : prm(prm)
    , increment(first_step)
  {}

  double AdaptiveLoadStepping::next() const
  {
    return std::min(1.0, s + increment);
  }

  void AdaptiveLoadStepping::converged(const unsigned int newton_iterations)
  {
    s = next();
    if (3 * newton_iterations <= 2 * prm.max_newton_iterations)
      increment = std::min(prm.max_load_step, 1.5 * increment);
  }

  bool AdaptiveLoadStepping::failed()
  {
    increment *= 0.25;
    return increment >= prm.min_load_step;
  }
} // namespace softchain::fem
