#pragma once
// AdaptiveLoadStepping: the path parameter s of a load path, from 0 (the
// start state) to 1 (the target), in steps that adapt to how hard Newton
// found the last one (Crisfield, Non-linear Finite Element Analysis of
// Solids and Structures, Vol. 1, Sec. 9.4, automatic increments):
//  - a step that converged in I Newton iterations scales the next one by
//    sqrt(I_d / I), kept within [1/2, 2] (and below Maximum load step), with
//    I_d = 5 desired iterations: an easy step lets the next grow, a hard one
//    shrinks it before it fails;
//  - a step that failed is retried from the last converged state with a
//    quarter of the increment, until it falls below Minimum load step (or
//    a path's own smallest step).
// Measured against growing by 1.5 after at most 8 of 12 iterations and
// never shrinking: docs/results.md, "The load step sized for five Newton
// iterations".
// It knows nothing of what s controls: pressure control (QuasiStaticSolver)
// and volume control (VolumeControlledInflation) both step with it.
#include <softchain/fem/parameters.h>

namespace softchain::fem
{
  class AdaptiveLoadStepping
  {
  public:
    // `first_step` is the first increment of s (e.g. Solver/Initial load step).
    AdaptiveLoadStepping(const SolverParameters &prm, double first_step);
    // The same, given up once a cut step falls below `min_step` instead.
    AdaptiveLoadStepping(const SolverParameters &prm, double first_step, double min_step);

    bool   finished() const { return s >= 1.0; }
    // The path parameter of the last converged state (0 before any).
    double reached() const { return s; }
    // The path parameter to try next: reached() + step, or 1 where that
    // would leave less than a quarter of the step to it.
    double next() const;
    double step() const { return increment; }

    // The attempt at next() converged in `newton_iterations`: s moves there.
    void converged(unsigned int newton_iterations);
    // The attempt at next() failed: the step is cut. Returns false when the
    // cut step is below the smallest step (the path is given up).
    bool failed();

  private:
    static constexpr double desired_iterations = 5;
    const SolverParameters &prm;
    const double            min_step;
    double                  s = 0.0;
    double                  increment;
  };
} // namespace softchain::fem
