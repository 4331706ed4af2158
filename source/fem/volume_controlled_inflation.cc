#include <softchain/fem/adaptive_load_stepping.h>
#include <softchain/fem/continuation_predictor.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  VolumeControlledInflation::VolumeControlledInflation(QuasiStaticSolver &solver,
                                                       const Parameters  &prm,
                                                       const double       start_pressure)
    : solver(solver)
    , prm(prm)
    , p(start_pressure)
  {}

  double VolumeControlledInflation::volume() const
  {
    return solver.pressure_load().cavity_volume(solver.displacement());
  }

  TrilinosWrappers::MPI::Vector VolumeControlledInflation::owned_displacement() const
  {
    const FiniteElementSpace     &s = solver.space();
    TrilinosWrappers::MPI::Vector u(s.owned_dofs, s.communicator);
    u = solver.displacement();
    return u;
  }

  TrilinosWrappers::MPI::Vector VolumeControlledInflation::unit_pressure_load() const
  {
    TrilinosWrappers::MPI::Vector g(solver.negative_residual());
    g = 0;
    solver.pressure_load().assemble(solver.displacement(), 1.0, solver.space().fixed_dofs, nullptr, g);
    g.compress(VectorOperation::add);
    return g;
  }

  LoadState VolumeControlledInflation::pressure_state() const
  {
    LoadState state;
    state.pressure = p;
    return state;
  }

  bool VolumeControlledInflation::newton(const double target_volume, Result &result, const bool final_state)
  {
    const FiniteElementSpace &s = solver.space();
    for (unsigned int it = 0; it <= prm.solver.max_newton_iterations; ++it)
      {
        if (!solver.assemble(pressure_state(), true))
          return false; // J <= 0 somewhere
        const TrilinosWrappers::MPI::Vector g        = unit_pressure_load();
        const double                        residual = solver.residual_bound();
        const double                        misfit   = target_volume - volume();
        // A step short of the target is a stepping stone, its residual
        // converged to the intermediate tolerance as under pressure control;
        // its volume is always the one asked for (the bordered Newton step
        // meets the linearised constraint, so the misfit falls quadratically).
        const double tolerance =
          final_state ? prm.solver.residual_tolerance : prm.solver.intermediate_tolerance;
        if (residual <= tolerance * std::max(std::abs(p) * g.l2_norm(), 1e-300) &&
            std::abs(misfit) <= prm.solver.residual_tolerance * target_volume)
          return true;
        if (it == prm.solver.max_newton_iterations)
          break;
        ++result.newton_iterations;

        TrilinosWrappers::MPI::Vector a(s.owned_dofs, s.communicator), b(a);
        if (!solver.solve_tangent(solver.negative_residual(), a) || !solver.solve_tangent(g, b, true))
          return false;
        const double dp = (misfit - g * a) / (g * b);
        a.add(dp, b);
        if (!std::isfinite(a.l2_norm()) || !std::isfinite(dp))
          return false;
        solver.apply_update(a);
        p += dp;
      }
    return false;
  }

  VolumeControlledInflation::Result VolumeControlledInflation::solve(const double target_volume)
  {
    Result               result;
    const double         v_start = volume();
    AdaptiveLoadStepping path(prm.solver, prm.solver.initial_load_step);
    ContinuationPredictor predictor(owned_displacement(), p);
    std::vector<TensionOnlyLaw::State> links_converged = solver.link_states();
    result.curve.push_back({v_start, p});
    while (!path.finished())
      {
        const unsigned int            before = result.newton_iterations;
        TrilinosWrappers::MPI::Vector u_predicted(predictor.last());
        if (prm.solver.secant_predictor && predictor.predict(path.next(), u_predicted, &p))
          solver.move_to(u_predicted);
        if (newton(v_start + path.next() * (target_volume - v_start), result, path.next() >= 1.0))
          {
            path.converged(result.newton_iterations - before);
            predictor.converged(path.reached(), owned_displacement(), p);
            links_converged = solver.link_states();
            result.curve.push_back({volume(), p});
            continue;
          }
        // Back to the last converged state (the curve's last point).
        solver.restore(predictor.last(), links_converged);
        p = result.curve.back().pressure;
        if (!path.failed())
          {
            std::ostringstream why;
            why << "volume control did not converge even with volume steps below "
                << prm.solver.min_load_step << " (last converged V = " << result.curve.back().volume
                << " m^3, p = " << p << " Pa)";
            result.reason = why.str();
            solver.set_state(predictor.last(), pressure_state());
            return result;
          }
      }
    result.converged = true;
    solver.set_state(owned_displacement(), pressure_state());
    return result;
  }
} // namespace softchain::fem
