#include <softchain/fem/adaptive_load_stepping.h>
#include <softchain/fem/load_path.h>

namespace softchain::fem
{
  LoadPath::LoadPath(const Parameters &prm, const double first_step, std::string name,
                     std::ostream &log)
    : prm(prm)
    , first_step(first_step)
    , name(std::move(name))
    , log(log)
  {}

  LoadPath::Result LoadPath::follow(LoadPathProblem &problem, std::vector<double> *history)
  {
    Result               result;
    AdaptiveLoadStepping path(prm.solver, first_step);
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
        const bool    final      = s >= 1.0 || problem.path_dependent();
        NewtonSystem &system     = problem.begin_step(s);
        auto          outcome    = newton.solve(system, final, history);
        unsigned int  iterations = outcome.iterations;
        // The step rule's measure of the step: its iterations to the
        // intermediate tolerance, also where Newton goes on to the final
        // ones (a path-dependent problem, friction). The iterations beyond
        // it (2-5 per step on P10 pressed with friction) say how tight the
        // final tolerances are, not how nonlinear the step was; counted in,
        // they halved the steps (docs/contact.md, "Cost").
        unsigned int  sizing     = outcome.iterations_to_intermediate;
        while (outcome.converged() && problem.augment())
          {
            outcome = newton.solve(system, final, history);
            iterations += outcome.iterations;
            sizing += outcome.iterations_to_intermediate;
            ++result.augmentations;
          }
        result.newton_iterations += iterations;
        if (outcome.converged())
          {
            path.converged(sizing);
            problem.accept_step(s);
            ++result.load_steps;
            log << "    load step " << result.load_steps << ": " << name << ' ' << path.reached()
                << ", " << iterations << " Newton iterations\n";
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
