#include <softchain/fem/bordered_load_control.h>

#include <algorithm>
#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  BorderedLoadControl::BorderedLoadControl(QuasiStaticSolver &solver, const Parameters &prm,
                                           const double start_load)
    : solver(solver)
    , prm(prm)
    , mu(start_load)
    , obstacle_motion(solver.load_state().obstacle_motion)
  {}

  LoadState BorderedLoadControl::loads() const
  {
    LoadState state       = load_at(mu);
    state.obstacle_motion = obstacle_motion;
    return state;
  }

  bool BorderedLoadControl::assemble(const bool with_matrix)
  {
    if (!solver.assemble(loads(), with_matrix))
      return false; // J <= 0 somewhere
    q      = unit_load();
    misfit = c_target - conjugate_displacement();
    return true;
  }

  // A step short of the path's end is a stepping stone, its residual
  // converged to the intermediate tolerance as under load control. Its c is
  // the one asked for: the bordered Newton step meets the linearised
  // constraint, so the misfit falls quadratically (at once where c is linear
  // in u).
  bool BorderedLoadControl::residual_converged(const double residual, const double tolerance) const
  {
    const double scale = std::max(std::abs(c_target), std::abs(c_end - c_start));
    return solver.residual_converged(residual, tolerance) &&
           std::abs(misfit) <= prm.solver.residual_tolerance * scale;
  }

  bool BorderedLoadControl::solve_correction(const bool same_tangent, const double forcing)
  {
    const FiniteElementSpace     &s = solver.space();
    TrilinosWrappers::MPI::Vector b(s.owned_dofs, s.communicator);
    du.reinit(b);
    if (!solver.solve_tangent(solver.negative_residual(), du, same_tangent, forcing) ||
        !solver.solve_tangent(q, b, true, forcing))
      return false;
    dmu = (misfit - q * du) / (q * b);
    du.add(dmu, b);
    return std::isfinite(du.l2_norm()) && std::isfinite(dmu);
  }

  void BorderedLoadControl::apply_correction()
  {
    solver.apply_update(du);
    mu += dmu;
  }

  void BorderedLoadControl::scale_correction(const double factor)
  {
    solver.scale_correction(factor);
    du *= factor;
    mu += (factor - 1.0) * dmu;
    dmu *= factor;
  }

  NewtonSystem &BorderedLoadControl::begin_step(const double s)
  {
    TrilinosWrappers::MPI::Vector u_predicted(predictor->last());
    const double                  mu_last = mu;
    if (prm.solver.secant_predictor && predictor->predict(s, u_predicted, &mu))
      {
        const double fraction = solver.stop_at_contact(predictor->last(), u_predicted, obstacle_motion);
        mu                    = mu_last + fraction * (mu - mu_last);
        solver.move_to(u_predicted);
      }
    c_target      = c_start + s * (c_end - c_start);
    augmentations = 0;
    return *this;
  }

  void BorderedLoadControl::accept_step(const double s)
  {
    predictor->converged(s, solver.owned_displacement(), mu);
    links_converged   = solver.link_states();
    contact_converged = solver.accept_contact_state(obstacle_motion);
    points->push_back({conjugate_displacement(), mu});
  }

  bool BorderedLoadControl::augment()
  {
    if (augmentations == prm.contact.max_augmentations || !solver.augment_contact(obstacle_motion))
      return false;
    ++augmentations;
    return true;
  }

  // Back to the last converged state (the path's last point).
  void BorderedLoadControl::reject_step()
  {
    solver.restore(predictor->last(), links_converged);
    solver.restore_contact(contact_converged);
    mu = points->back().load;
  }

  BorderedLoadControl::Path BorderedLoadControl::follow(const double end, const double first_step,
                                                        const std::string &name)
  {
    Path path;
    c_start         = conjugate_displacement();
    c_end           = end;
    predictor       = std::make_unique<ContinuationPredictor>(solver.owned_displacement(), mu);
    links_converged = solver.link_states();
    if (solver.obstacle_contact())
      contact_converged = solver.obstacle_contact()->history();
    points = &path.points;
    path.points.push_back({c_start, mu});
    path.steps = LoadPath(prm, first_step, name, solver.log_stream()).follow(*this);
    solver.set_state(predictor->last(), loads());
    points = nullptr;
    return path;
  }
} // namespace softchain::fem
