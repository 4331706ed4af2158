#include <softchain/fem/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <vector>

namespace softchain::fem
{
  NewtonSolver::NewtonSolver(const SolverParameters &prm, const bool verbose, std::ostream &log)
    : prm(prm)
    , verbose(verbose)
    , log(log)
  {}

  NewtonSolver::Outcome NewtonSolver::solve(NewtonSystem &system, const bool final_state,
                                            std::vector<double> *history)
  {
    const double residual_tolerance = final_state ? prm.residual_tolerance : prm.intermediate_tolerance;
    const double error_tolerance = final_state ? prm.displacement_tolerance : prm.intermediate_tolerance;
    const auto   error_converged = [&](const double error) {
      return error <= error_tolerance * std::max(system.solution_norm(), 1e-300);
    };
    double       s0              = 0.0; // dx . R before the step
    unsigned int inverting_steps = 0;   // full Newton steps that inverted an element
    // |R| of every iterate, and whether the last step was taken where Newton
    // had stalled (stalled()).
    std::vector<double> residuals;
    bool                damped = false;
    const auto   outcome         = [](const Status status, const unsigned int it) {
      return Outcome{status, it};
    };
    for (unsigned int it = 0; it <= prm.max_newton_iterations; ++it)
      {
        bool valid = system.assemble(true);
        // A second full Newton step that inverts an element gives the load
        // step up: it is too large for this mesh. Measured on P10 (Q2 hex,
        // 40 kPa from rest): no load step that converged had one such step,
        // while each that failed had them in 5-12 iterations, with 20-45
        // halvings, a quarter of the solve's time.
        if (it > 0 && !valid && ++inverting_steps == 2)
          return outcome(Status::inverted, it);
        if (it > 0 && prm.line_search && (!valid || system.energy_line_search()))
          valid = line_search(system, s0, valid);
        if (!valid)
          return outcome(Status::inverted, it);
        double residual = system.residual_norm();
        if (damped)
          residual = backtrack(system, residual, residuals.back());
        residuals.push_back(residual);
        if (it == 0)
          system.first_residual(residual);
        if (history)
          history->push_back(residual);
        if (!std::isfinite(residual))
          return outcome(Status::not_finite, it);
        // An exact equilibrium (no load at rest), if the system's other
        // conditions hold there too (a volume control's volume).
        if (residual == 0.0 && system.residual_converged(residual, residual_tolerance))
          return outcome(Status::converged, it);
        bool correction_ready = false;
        if (it > 0 && system.residual_converged(residual, residual_tolerance))
          {
            // The error |x* - x|: the last update bounds it (quadratic
            // convergence leaves far less); else the simplified Newton
            // correction from the last factors estimates it, one pair of
            // triangular solves instead of a new factorisation whose update
            // would then be applied and checked. Without kept factors the
            // correction is Newton's own next step.
            if (error_converged(system.correction_norm()))
              return outcome(Status::converged, it);
            if (!system.solve_correction(true, forcing(system, residual, final_state)))
              return outcome(Status::linear_failure, it);
            if (verbose)
              log << "      error estimate |K^-1 R| = " << std::scientific << std::setprecision(3)
                  << system.correction_norm() << std::defaultfloat << '\n';
            if (error_converged(system.correction_norm()))
              return outcome(Status::converged, it);
            correction_ready = !system.keeps_factorisation();
          }
        if (it == prm.max_newton_iterations)
          break;
        if (!correction_ready && !system.solve_correction(false, forcing(system, residual, final_state)))
          return outcome(Status::linear_failure, it);
        s0     = system.correction_slope();
        damped = system.backtrack_when_stalled() && stalled(residuals);
        if (verbose)
          log << "      Newton " << std::setw(2) << it << "  |R| = " << std::scientific
              << std::setprecision(3) << residual << "  |du| = " << system.correction_norm()
              << std::defaultfloat << '\n';
        const double admissible = system.admissible_fraction();
        system.apply_correction();
        if (admissible < 1.0)
          {
            system.scale_correction(admissible);
            s0 *= admissible;
            if (verbose)
              log << "      step limited to " << admissible << " (contact points entering)\n";
          }
      }
    return outcome(Status::not_converged, prm.max_newton_iterations);
  }

  // The linear residual a correction may leave, eta |R|. In the path's last
  // step, a hundredth of the Residual tolerance relative to |R|: the state
  // Newton returns is then as exact as with a direct solve (1-rank and
  // 2-rank answers, mirror-symmetric loads, agree far inside the
  // tolerances). In a stepping stone, whose state only starts the next
  // step, a hundredth of what its convergence test allows (Intermediate
  // tolerance times the residual's scale), so that it never decides that
  // test, but at most 1e-5 |R|, so that each step keeps Newton's direction:
  // loose far from the solution and tight near it in absolute terms, as in
  // Kelley (Iterative Methods for Linear and Nonlinear Equations, SIAM 1995,
  // Sec. 6.3). On P10 with fibre sheets at 4 mm this cut the GMRES
  // iterations on single-precision factors (SerialDirectSolver) from 5.5 to
  // 3.0 a solve, with the same 57 Newton iterations; at 2.4 mm the solve
  // took 83 s against 91 s with every correction at 1e-8, in the same 72
  // iterations. A cap of 1e-3 saved a few more GMRES iterations but moved
  // the 2.4 mm path: 80 Newton iterations in 13 load steps, 99 s.
  double NewtonSolver::forcing(const NewtonSystem &system, const double residual, const bool final_state) const
  {
    const double strict = prm.residual_tolerance / 100;
    if (final_state || !(residual > 0))
      return strict;
    return std::clamp(0.01 * prm.intermediate_tolerance * system.residual_scale() / residual, strict, 1e-5);
  }

  // Newton has stalled when two iterations have not halved |R|. Where a
  // contact point's friction switches between stick and slip, the full
  // steps of a compliant finger cycle: P10 with fibre sheets (4 mm across,
  // 8 mm along the finger) pressed onto the table with mu = 0.5 at 13.4 kPa
  // alternated between |R| = 2.2e-2 and 2.8e-2 with |du| = 0.5 mm (the
  // tip sliding back and forth) until the load step could not be cut
  // further. A converging Newton halves |R| in far fewer than two
  // iterations.
  bool NewtonSolver::stalled(const std::vector<double> &residuals)
  {
    const std::size_t n = residuals.size();
    return n >= 3 && residuals[n - 1] > 0.5 * residuals[n - 3];
  }

  // Backtracking on |R| (Dennis and Schnabel, Numerical Methods for
  // Unconstrained Optimization and Nonlinear Equations, SIAM 1996, Ch. 6:
  // the Newton step descends on |R|^2 / 2 where R is differentiable).
  double NewtonSolver::backtrack(NewtonSystem &system, double residual, const double before)
  {
    double step = 1.0, best_step = 1.0, best = residual;
    for (unsigned int k = 0; k < 4 && !(best < before); ++k)
      {
        system.scale_correction(0.5);
        step *= 0.5;
        const bool   valid = system.assemble(true);
        const double r     = valid ? system.residual_norm() : std::numeric_limits<double>::infinity();
        if (verbose)
          log << "      stalled: step " << step << "  |R| = " << std::scientific << std::setprecision(3)
              << r << std::defaultfloat << '\n';
        if (r < best)
          {
            best      = r;
            best_step = step;
          }
      }
    if (step != best_step)
      {
        system.scale_correction(best_step / step);
        system.assemble(true);
      }
    return best;
  }

  // With s(a) = dx . R(x_old + a dx), s(0) = -dx.K dx < 0: the full step
  // is kept when |s(1)| <= 0.8 |s(0)| (the residual norm itself may grow in
  // a good step of a nearly incompressible solid), else the step goes to
  // the zero of the secant of s, within [0.1, 1].
  bool NewtonSolver::line_search(NewtonSystem &system, const double s0, const bool valid)
  {
    double step = 0.5;
    if (valid)
      {
        const double s1 = system.correction_slope();
        if (std::abs(s1) <= 0.8 * std::abs(s0))
          return true;
        step = std::clamp(s0 / (s0 - s1), 0.1, 1.0);
      }
    for (unsigned int k = 0; k < 6; ++k)
      {
        system.scale_correction(step);
        if (verbose)
          log << "      line search: step " << step << '\n';
        if (system.assemble(true))
          return true;
        step = 0.5;
      }
    return false;
  }
} // namespace softchain::fem
