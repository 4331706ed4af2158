#include <softchain/fem/adaptive_load_stepping.h>
#include <softchain/fem/load_path.h>

namespace softchain::fem
{
  LoadPath::LoadPath(const Parameters &prm, const double first_step, std::string name,
                     std::ostream &log)
    : LoadPath(prm, first_step, prm.solver.min_load_step, std::move(name), log)
  {}

  LoadPath::LoadPath(const Parameters &prm, const double first_step, const double min_step,
                     std::string name, std::ostream &log)
    : prm(prm)
    , first_step(first_step)
    , min_step(min_step)
    , name(std::move(name))
    , log(log)
  {}

  LoadPath::Result LoadPath::follow(LoadPathProblem &problem, std::vector<double> *history)
  {
    Result               result;
    AdaptiveLoadStepping path(prm.solver, first_step, min_step);
    NewtonSolver         newton(prm.solver, prm.output.verbose, log);
    while (!path.finished())
      {
        if (result.attempts == prm.solver.max_load_step_attempts)
          {
            result.stop = Stop::too_many_attempts;
            break;
          }
        ++result.attempts;
        const double  s          = path.next();
        NewtonSystem &system     = problem.begin_step(s);
        const bool    at_end     = s >= 1.0;
        auto          outcome    = newton.solve(system, at_end, history);
        unsigned int  iterations = outcome.iterations;
        // Uzawa's updates of the contact pressures (augment()) come at the
        // path's end only, each followed by Newton to the final tolerances:
        // multipliers set at a stepping stone stay on points that lift off
        // later (by less than the penetration tolerance) and push there. On
        // P10 closing on a cylinder at 40 kPa, the obstacle's force lay 1.6 %
        // from the converged one (penalty factor 100, tolerance 1e-4) with
        // updates at every step, 0.75 % with updates at the end
        // (docs/contact.md, "The method").
        while (at_end && outcome.converged() && problem.augment())
          {
            outcome = newton.solve(system, true, history);
            iterations += outcome.iterations;
            ++result.augmentations;
          }
        result.newton_iterations += iterations;
        if (outcome.converged())
          {
            path.converged(iterations);
            problem.accept_step(s);
            ++result.load_steps;
            log << "    load step " << result.load_steps << ": " << name << ' ' << path.reached()
                << ", " << iterations << " Newton iterations\n";
            if (problem.goal_reached())
              break;
            continue;
          }
        problem.reject_step();
        result.last_failure = outcome.status;
        const bool more     = path.failed();
        log << "    " << name << ' ' << s << " failed (" << describe(outcome.status)
            << "); cutting the step to " << path.step() << '\n';
        if (!more)
          {
            result.stop = Stop::step_too_small;
            break;
          }
      }
    result.reached = path.reached();
    return result;
  }

  std::string describe(const NewtonSolver::Status status)
  {
    switch (status)
      {
        case NewtonSolver::Status::converged:
          return "converged";
        case NewtonSolver::Status::inverted:
          return "an element inverted, J <= 0";
        case NewtonSolver::Status::linear_failure:
          return "the linear solver failed";
        case NewtonSolver::Status::not_finite:
          return "the residual is not finite";
        case NewtonSolver::Status::not_converged:
          break;
      }
    return "Newton did not converge";
  }
} // namespace softchain::fem
