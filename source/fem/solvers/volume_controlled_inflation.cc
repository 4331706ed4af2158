#include <softchain/data/content_hash.h>
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
    , obstacle_motion(solver.load_state().obstacle_motion)
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
    state.pressure        = p;
    state.obstacle_motion = obstacle_motion;
    return state;
  }

  bool VolumeControlledInflation::assemble(const bool with_matrix)
  {
    if (!solver.assemble(pressure_state(), with_matrix))
      return false; // J <= 0 somewhere
    g      = unit_pressure_load();
    misfit = v_target - volume();
    return true;
  }

  // A step short of the target is a stepping stone, its residual converged
  // to the intermediate tolerance as under pressure control; its volume is
  // always the one asked for (the bordered Newton step meets the linearised
  // constraint, so the misfit falls quadratically).
  bool VolumeControlledInflation::residual_converged(const double residual, const double tolerance) const
  {
    return residual <= tolerance * std::max(std::abs(p) * g.l2_norm(), 1e-300) &&
           std::abs(misfit) <= prm.solver.residual_tolerance * v_target;
  }

  bool VolumeControlledInflation::solve_correction(const bool same_tangent)
  {
    const FiniteElementSpace     &s = solver.space();
    TrilinosWrappers::MPI::Vector b(s.owned_dofs, s.communicator);
    du.reinit(b);
    if (!solver.solve_tangent(solver.negative_residual(), du, same_tangent) ||
        !solver.solve_tangent(g, b, true))
      return false;
    dp = (misfit - g * du) / (g * b);
    du.add(dp, b);
    return std::isfinite(du.l2_norm()) && std::isfinite(dp);
  }

  void VolumeControlledInflation::apply_correction()
  {
    solver.apply_update(du);
    p += dp;
  }

  void VolumeControlledInflation::scale_correction(const double factor)
  {
    solver.scale_correction(factor);
    du *= factor;
    p += (factor - 1.0) * dp;
    dp *= factor;
  }

  NewtonSystem &VolumeControlledInflation::begin_step(const double s)
  {
    TrilinosWrappers::MPI::Vector u_predicted(predictor->last());
    const double                  p_last = p;
    if (prm.solver.secant_predictor && predictor->predict(s, u_predicted, &p))
      {
        const double fraction = solver.stop_at_contact(predictor->last(), u_predicted, obstacle_motion);
        p                     = p_last + fraction * (p - p_last);
        solver.move_to(u_predicted);
      }
    v_target      = v_start + s * (v_end - v_start);
    augmentations = 0;
    return *this;
  }

  void VolumeControlledInflation::accept_step(const double s)
  {
    predictor->converged(s, owned_displacement(), p);
    links_converged = solver.link_states();
    contact_converged = solver.accept_contact_state(obstacle_motion);
    curve->push_back({volume(), p});
  }

  bool VolumeControlledInflation::augment()
  {
    if (augmentations == prm.contact.max_augmentations || !solver.augment_contact(obstacle_motion))
      return false;
    ++augmentations;
    return true;
  }

  // Back to the last converged state (the curve's last point).
  void VolumeControlledInflation::reject_step()
  {
    solver.restore(predictor->last(), links_converged);
    solver.restore_contact(contact_converged);
    p = curve->back().pressure;
  }

  VolumeControlledInflation::Result VolumeControlledInflation::solve(const double target_volume)
  {
    Result result;
    v_start         = volume();
    v_end           = target_volume;
    predictor       = std::make_unique<ContinuationPredictor>(owned_displacement(), p);
    links_converged = solver.link_states();
    if (solver.obstacle_contact())
      contact_converged = solver.obstacle_contact()->history();
    curve           = &result.curve;
    result.curve.push_back({v_start, p});
    std::ostringstream log;
    const auto         path =
      LoadPath(prm, prm.solver.initial_load_step, "volume factor", log).follow(*this);
    result.newton_iterations = path.newton_iterations;
    result.converged         = path.finished();
    if (!result.converged)
      {
        std::ostringstream why;
        why << "volume control did not converge "
            << (path.stop == LoadPath::Stop::too_many_attempts ?
                  "in " + std::to_string(path.attempts) + " volume steps (Solver/Maximum load step attempts)" :
                  "even with volume steps below " + data::canonical(prm.solver.min_load_step))
            << " (last converged V = " << result.curve.back().volume << " m^3, p = " << p << " Pa)";
        result.reason = why.str();
      }
    solver.set_state(predictor->last(), pressure_state());
    curve = nullptr;
    return result;
  }
} // namespace softchain::fem
