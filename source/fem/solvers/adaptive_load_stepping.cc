#include <softchain/fem/adaptive_load_stepping.h>

#include <algorithm>
#include <cmath>

namespace softchain::fem
{
  AdaptiveLoadStepping::AdaptiveLoadStepping(const SolverParameters &prm, const double first_step)
    : AdaptiveLoadStepping(prm, first_step, prm.min_load_step)
  {}

  AdaptiveLoadStepping::AdaptiveLoadStepping(const SolverParameters &prm, const double first_step,
                                             const double min_step)
    : prm(prm)
    , min_step(min_step)
    , increment(first_step)
  {}

  // A step that would leave less than a quarter of itself to the path's end
  // goes to the end (if Maximum load step allows): the sliver of a last step would cost the final
  // tolerances' Newton iterations for a load change Newton takes in its stride.
  double AdaptiveLoadStepping::next() const
  {
    const double rest = 1.0 - s;
    return rest <= 1.25 * increment && rest <= prm.max_load_step ? 1.0 : s + increment;
  }

  // Crisfield's rule: the next increment is the last one times
  // sqrt(I_d / I), I the Newton iterations the last step took to the
  // intermediate tolerance (LoadPath) and I_d the desired count, within
  // [1/2, 2] of the last.
  void AdaptiveLoadStepping::converged(const unsigned int newton_iterations)
  {
    s = next();
    const double factor = std::sqrt(desired_iterations / std::max(1u, newton_iterations));
    increment           = std::min(prm.max_load_step, std::clamp(factor, 0.5, 2.0) * increment);
  }

  bool AdaptiveLoadStepping::failed()
  {
    increment *= 0.25;
    return increment >= min_step;
  }
} // namespace softchain::fem
