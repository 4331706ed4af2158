#include <softchain/fem/boundary_ids.h>
#include <softchain/data/input_error.h>
#include <softchain/fem/continuation_predictor.h>
#include <softchain/fem/quasi_static_solver.h>
#include <softchain/fem/cell_conforming_polylines.h>
#include <softchain/fem/hyperelastic_cell.h>

#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // WorkStream scratch and copy data of the cell assembly (step-44 style).
    struct CellScratch
    {
      CellScratch(const FiniteElementSpace &space)
        : fe_values(*space.mapping, *space.fe, space.cell_quadrature,
                    update_values | update_gradients | update_JxW_values)
        , grad_u(space.cell_quadrature.size())
        , cell(*space.fe)
        , cell_u(space.fe->n_dofs_per_cell())
      {}
      CellScratch(const CellScratch &other)
        : fe_values(other.fe_values.get_mapping(), other.fe_values.get_fe(),
                    other.fe_values.get_quadrature(), other.fe_values.get_update_flags())
        , grad_u(other.grad_u)
        , cell(other.cell)
        , cell_u(other.cell_u)
      {}
      FEValues<3>               fe_values;
      std::vector<Tensor<2, 3>> grad_u;
      HyperelasticCell          cell;
      Vector<double>            cell_u; // the cell's DoF values, for its springs
    };

    struct CellCopy
    {
      CellCopy(unsigned int n)
        : matrix(n, n), rhs(n), dofs(n)
      {}
      FullMatrix<double>                   matrix;
      Vector<double>                       rhs;
      std::vector<types::global_dof_index> dofs;
      unsigned int                         cell_index = 0;
      bool                                 inverted   = false;
      double                               tension_mismatch = 0; // EmbeddedSpringNetwork::assemble_cell
    };

    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  QuasiStaticSolver::QuasiStaticSolver(const Parameters                  &parameters,
                                       const Triangulation<3>            &serial_mesh,
                                       const std::vector<std::string>    &material_names,
                                       const std::vector<SpringPolyline> &spring_polylines,
                                       const std::vector<FibreSheet>     &fibre_sheets,
                                       MPI_Comm                           communicator,
                                       std::ostream                      &log_stream)
    : prm(parameters)
    , log(log_stream)
    , fe_space(std::make_unique<FiniteElementSpace>(serial_mesh, parameters.mesh.element_type,
                                                    communicator))
    , computing_timer(communicator, log_stream, TimerOutput::never, TimerOutput::wall_times)
    , tangent_solver(TangentSolver::create(parameters.solver, *fe_space, log_stream))
  {
    for (const auto &name : material_names)
      {
        const auto region = prm.materials.regions.find(name);
        if (region == prm.materials.regions.end())
          throw data::InputError(prm.file + ": the mesh has material region '" + name +
                                 "' but subsection Materials has no subsection '" + name + "'");
        materials.push_back(HyperelasticMaterial::create(prm.materials.strain_energy,
                                                         region->second.youngs_modulus,
                                                         region->second.poissons_ratio));
      }
    pressure     = std::make_unique<FollowerPressure>(*fe_space);
    tip_traction = std::make_unique<DeadSurfaceTraction>(*fe_space, boundary::tip);
    if (!spring_polylines.empty() || !fibre_sheets.empty())
      springs = std::make_unique<EmbeddedSpringNetwork>(*fe_space,
                                                         cell_conforming_polylines(
                                                           spring_polylines, serial_mesh,
                                                           *fe_space->mapping),
                                                         fibre_sheets,
                                                         prm.springs.axial_rigidity,
                                                         prm.springs.smoothing_strain);
    for (const auto &name : material_names)
      youngs_moduli.push_back(prm.materials.regions.at(name).youngs_modulus);
    set_contact(prm.contact);
    setup_system();
  }

  void QuasiStaticSolver::set_contact(const geometry::ContactScene &scene)
  {
    contact.reset();
    if (!scene.empty())
      contact = std::make_unique<ObstacleContact>(*fe_space, scene, youngs_moduli);
  }

  void QuasiStaticSolver::setup_system()
  {
    const FiniteElementSpace &s = *fe_space;
    setup_matrix(s.fixed_dofs, IndexSet(s.dof_handler.n_dofs()));
    u_owned.reinit(s.owned_dofs, s.communicator);
    du.reinit(s.owned_dofs, s.communicator);
    u_ghosted.reinit(s.owned_dofs, s.relevant_dofs, s.communicator);
    du_ghosted.reinit(s.owned_dofs, s.relevant_dofs, s.communicator);
    reset();
  }

  // The tangent's sparsity pattern and the residual's writable entries for
  // `constraints`, whose lines may couple the DoFs `coupled` (a point contact
  // couples every tip DoF) beyond the cells' couplings (the springs' are
  // their cells').
  void QuasiStaticSolver::setup_matrix(const AffineConstraints<double> &constraints,
                                       const IndexSet                  &coupled)
  {
    const FiniteElementSpace &s = *fe_space;
    writable_dofs = s.relevant_dofs;
    writable_dofs.add_indices(coupled);

    DynamicSparsityPattern pattern(writable_dofs);
    DoFTools::make_sparsity_pattern(s.dof_handler, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, s.owned_dofs, s.communicator,
                                               writable_dofs);
    matrix.reinit(s.owned_dofs, s.owned_dofs, pattern, s.communicator);
    friction_unsymmetric_part.clear(); // made with `matrix`'s pattern where friction needs it
    rhs.reinit(s.owned_dofs, writable_dofs, s.communicator, true);
    tangent_solver->pattern_changed();
    // The places need a pattern of the Dirichlet constraints alone (a point
    // contact's pattern drops the tip rows it condenses).
    scatter.reset();
    if (&constraints == &s.fixed_dofs && CellMatrixScatter::serves(s.fixed_dofs, s.communicator))
      scatter = std::make_unique<CellMatrixScatter>(s.dof_handler, s.fixed_dofs, matrix);
  }

  void QuasiStaticSolver::reset()
  {
    u_owned = 0;
    set_displacement(u_owned);
    load = LoadState();
    if (contact)
      contact->reset();
  }

  void QuasiStaticSolver::set_displacement(const TrilinosWrappers::MPI::Vector &owned_u)
  {
    move_to(owned_u);
    if (springs)
      springs->set_link_states(u_ghosted);
  }

  void QuasiStaticSolver::move_to(const TrilinosWrappers::MPI::Vector &owned_u)
  {
    u_owned   = owned_u;
    u_ghosted = u_owned;
  }

  std::vector<TensionOnlyLaw::State> QuasiStaticSolver::link_states() const
  {
    return springs ? springs->link_states() : std::vector<TensionOnlyLaw::State>();
  }

  ObstacleContact::History QuasiStaticSolver::accept_contact_state(const double obstacle_motion)
  {
    if (!contact)
      return {};
    contact->commit(u_ghosted, obstacle_motion);
    return contact->history();
  }

  bool QuasiStaticSolver::augment_contact(const double obstacle_motion)
  {
    return contact && contact->augment(u_ghosted, obstacle_motion);
  }

  void QuasiStaticSolver::restore_contact(const ObstacleContact::History &history)
  {
    if (contact)
      contact->restore(history);
  }

  void QuasiStaticSolver::restore(const TrilinosWrappers::MPI::Vector      &owned_u,
                                  const std::vector<TensionOnlyLaw::State> &links)
  {
    move_to(owned_u);
    if (springs)
      springs->restore_link_states(links);
  }

  bool QuasiStaticSolver::assemble_cells(const bool with_matrix, const double gravity_factor,
                                         const AffineConstraints<double> &constraints)
  {
    const FiniteElementSpace        &s = *fe_space;
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = s.fe->n_dofs_per_cell();
    Tensor<1, 3>                     body_force;
    body_force[1] = -9.81 * prm.materials.density * gravity_factor;
    std::atomic<bool> inverted(false);

    auto worker = [&](const DoFHandler<3>::active_cell_iterator &cell, CellScratch &scratch,
                      CellCopy &copy) {
      copy.rhs              = 0;
      copy.tension_mismatch = 0;
      copy.cell_index       = cell->active_cell_index();
      cell->get_dof_indices(copy.dofs);
      scratch.fe_values.reinit(cell);
      scratch.fe_values[displacement].get_function_gradients(u_ghosted, scratch.grad_u);
      FullMatrix<double> *cell_matrix = with_matrix ? &copy.matrix : nullptr;
      copy.inverted = !scratch.cell.assemble(scratch.fe_values, scratch.grad_u,
                                             *materials.at(cell->material_id()), body_force,
                                             cell_matrix, copy.rhs);
      if (springs && !copy.inverted) // the springs inside this cell
        {
          cell->get_dof_values(u_ghosted, scratch.cell_u);
          copy.tension_mismatch =
            springs->assemble_cell(cell->active_cell_index(), scratch.cell_u, cell_matrix, copy.rhs);
        }
    };

    const bool places = by_places(constraints);
    tension_mismatch = 0;
    auto copier = [&](const CellCopy &copy) {
      tension_mismatch += copy.tension_mismatch;
      if (copy.inverted)
        inverted = true;
      else if (places)
        scatter->add(copy.cell_index, copy.dofs, with_matrix ? &copy.matrix : nullptr, copy.rhs,
                     &matrix, rhs);
      else if (with_matrix)
        constraints.distribute_local_to_global(copy.matrix, copy.rhs, copy.dofs, matrix, rhs);
      else
        constraints.distribute_local_to_global(copy.rhs, copy.dofs, rhs);
    };

    using CellFilter = FilteredIterator<DoFHandler<3>::active_cell_iterator>;
    WorkStream::run(CellFilter(IteratorFilters::LocallyOwnedCell(), s.dof_handler.begin_active()),
                    CellFilter(IteratorFilters::LocallyOwnedCell(), s.dof_handler.end()),
                    worker, copier, CellScratch(s), CellCopy(n));
    tension_mismatch = Utilities::MPI::sum(tension_mismatch, s.communicator);
    return !Utilities::MPI::logical_or(inverted.load(), s.communicator);
  }

  bool QuasiStaticSolver::by_places(const AffineConstraints<double> &constraints) const
  {
    return scatter && &constraints == &fe_space->fixed_dofs;
  }

  void QuasiStaticSolver::assemble_point_loads(const std::vector<PointLoad>    &point_loads,
                                               const AffineConstraints<double> &constraints,
                                               TrilinosWrappers::MPI::Vector   &vector) const
  {
    std::vector<Point<3>> points;
    for (const auto &l : point_loads)
      points.push_back(l.point);
    const EmbeddedPoints located(*fe_space, points, "point load");
    for (unsigned int k = 0; k < located.size(); ++k)
      if (located.owned(k))
        {
          const auto    &stencil = located.stencil(k);
          Vector<double> local(stencil.dof.size());
          for (unsigned int i = 0; i < stencil.dof.size(); ++i)
            local(i) = stencil.weight[i] * point_loads[k].force[stencil.component[i]];
          constraints.distribute_local_to_global(local, stencil.dof, vector);
        }
  }

  TrilinosWrappers::MPI::Vector
  QuasiStaticSolver::point_load_vector(const std::vector<PointLoad> &point_loads) const
  {
    TrilinosWrappers::MPI::Vector q(rhs);
    q = 0;
    assemble_point_loads(point_loads, active_constraints ? *active_constraints : fe_space->fixed_dofs, q);
    q.compress(VectorOperation::add);
    return q;
  }

  bool QuasiStaticSolver::assemble(const LoadState &state, const bool with_matrix)
  {
    return assemble_with(state, with_matrix,
                         active_constraints ? *active_constraints : fe_space->fixed_dofs);
  }

  const TrilinosWrappers::MPI::Vector &QuasiStaticSolver::support_forces()
  {
    // The next Newton iteration assembles anew: rhs and f_ext_norm may change here.
    AffineConstraints<double> none;
    none.close();
    if (springs) // the law's tensions, not the last Newton iterate's
      springs->set_link_states(u_ghosted);
    assemble_with(load, false, none);
    return rhs;
  }

  bool QuasiStaticSolver::assemble_with(const LoadState &state, const bool with_matrix,
                                        const AffineConstraints<double> &constraints)
  {
    TimerOutput::Scope timer_section(computing_timer, "assembly");
    const bool friction = with_matrix && contact && contact->has_friction();
    if (with_matrix)
      matrix = 0;
    if (friction && friction_unsymmetric_part.m() == 0)
      friction_unsymmetric_part.reinit(matrix);
    if (friction)
      friction_unsymmetric_part = 0;
    rhs = 0;
    // External loads first: their norm scales the convergence test.
    if (state.pressure != 0.0)
      pressure->assemble(u_ghosted, state.pressure, constraints, with_matrix ? &matrix : nullptr,
                         rhs, by_places(constraints) ? scatter.get() : nullptr);
    if (!state.point_loads.empty())
      assemble_point_loads(state.point_loads, constraints, rhs);
    if (state.tip_traction.norm() > 0)
      tip_traction->assemble(state.tip_traction, constraints, rhs);
    // The obstacles' contact forces count among the external loads (their
    // norm scales the convergence test where they are the only load).
    if (contact)
      contact->assemble(u_ghosted, state.obstacle_motion, constraints,
                        with_matrix ? &matrix : nullptr, rhs,
                        friction ? &friction_unsymmetric_part : nullptr);
    rhs.compress(VectorOperation::add);
    f_ext_norm = rhs.l2_norm();

    const bool valid = assemble_cells(with_matrix, state.gravity_factor, constraints);
    if (with_matrix)
      matrix.compress(VectorOperation::add);
    if (friction)
      friction_unsymmetric_part.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    return valid;
  }

  bool QuasiStaticSolver::keeps_factorisation() const
  {
    return tangent_solver->keeps_factorisation();
  }

  bool QuasiStaticSolver::solve_tangent(const TrilinosWrappers::MPI::Vector &b,
                                        TrilinosWrappers::MPI::Vector       &x,
                                        const bool                           same_tangent,
                                        const double                         forcing)
  {
    TimerOutput::Scope timer_section(computing_timer, "linear solve");
    x = 0;
    const bool friction = contact && contact->has_friction();
    if (!tangent_solver->solve(matrix, friction ? &friction_unsymmetric_part : nullptr, b, x, same_tangent, forcing))
      return false;
    (active_constraints ? *active_constraints : fe_space->fixed_dofs).distribute(x);
    return std::isfinite(x.l2_norm());
  }

  void QuasiStaticSolver::apply_update(const TrilinosWrappers::MPI::Vector &update)
  {
    if (springs)
      {
        du_ghosted = update;
        springs->prepare_link_updates(u_ghosted, du_ghosted);
      }
    if (&update != &du)
      du = update;
    correction_taken = 1.0;
    u_owned += update;
    u_ghosted = u_owned;
    if (springs)
      springs->move_link_states(1.0);
  }

  // u = u_old + factor (u - u_old), the springs' link states moved along
  // their Newton step by the same total fraction.
  void QuasiStaticSolver::scale_correction(const double factor)
  {
    u_owned.add(factor - 1.0, du);
    du *= factor;
    correction_taken *= factor;
    u_ghosted = u_owned;
    if (springs)
      springs->move_link_states(correction_taken);
  }

  double QuasiStaticSolver::admissible_fraction()
  {
    return admissible_fraction(du, newton_target.obstacle_motion);
  }

  double QuasiStaticSolver::admissible_fraction(const TrilinosWrappers::MPI::Vector &step, const double motion)
  {
    if (!contact)
      return 1.0;
    TrilinosWrappers::MPI::Vector stepped(u_owned);
    stepped += step;
    return contact_entry_fraction(u_owned, stepped, motion);
  }

  double QuasiStaticSolver::stop_at_contact(const TrilinosWrappers::MPI::Vector &from,
                                            TrilinosWrappers::MPI::Vector &to, const double motion)
  {
    const double fraction = contact_entry_fraction(from, to, motion);
    if (fraction < 1.0)
      to.sadd(fraction, 1.0 - fraction, from);
    return fraction;
  }

  // Contact points may enter an obstacle by 2 % of their face's size in one
  // Newton step or prediction: with the default penalty (factor 10) that
  // is the penetration of a contact pressure of 0.2 E, above what P10 meets
  // at 40 kPa (penetrations up to 0.8 % of h: docs/contact.md, "Cost"); 5 %
  // took the same Newton iterations there.
  double QuasiStaticSolver::contact_entry_fraction(const TrilinosWrappers::MPI::Vector &from,
                                                   const TrilinosWrappers::MPI::Vector &to,
                                                   const double                         motion)
  {
    if (!contact)
      return 1.0;
    constexpr double entry_depth = 0.02;
    if (from_ghosted.size() != u_ghosted.size())
      {
        from_ghosted.reinit(u_ghosted);
        to_ghosted.reinit(u_ghosted);
      }
    from_ghosted = from;
    to_ghosted   = to;
    return contact->entry_fraction(from_ghosted, to_ghosted, motion, entry_depth);
  }

  double QuasiStaticSolver::residual_bound() const
  {
    return rhs.l2_norm() + tension_mismatch;
  }

  // A solve whose loads may all be prescribed motion (f_ext = 0) measures
  // its residual against the one right after the first step moved the tip.
  void QuasiStaticSolver::first_residual(const double residual)
  {
    if (newton_target.tip_motion && motion_residual_scale == 0.0)
      motion_residual_scale = residual;
  }

  // The residual's scale: the external loads, a prescribed motion's first
  // residual, or (a scene with neither) the springs' rest tension.
  double QuasiStaticSolver::residual_scale() const
  {
    return std::max({f_ext_norm, motion_residual_scale, springs ? springs->rest_force() : 0.0, 1e-300});
  }

  bool QuasiStaticSolver::residual_converged(const double residual, const double tolerance) const
  {
    return residual <= tolerance * residual_scale();
  }

  void QuasiStaticSolver::anchor_tip_motion(const bool point_contact)
  {
    if (!prescribed_tip || prescribed_tip->point_contact() != point_contact)
      {
        prescribed_tip = std::make_unique<PrescribedTip>(*fe_space, point_contact);
        // A point contact's constraints couple all tip DoFs: widen the
        // pattern once (it then serves the face-held motions too).
        if (point_contact && !pattern_couples_tip)
          {
            setup_matrix(prescribed_tip->constraints(), prescribed_tip->coupled_dofs());
            pattern_couples_tip = true;
          }
      }
    prescribed_tip->anchor(u_owned);
  }

  // A solve to a target with a tip motion holds the tip DoFs; the motion is
  // relative to the state where it was first prescribed (anchored there).
  void QuasiStaticSolver::prepare_tip_motion(const LoadState &target)
  {
    motion_residual_scale = 0.0;
    if (!target.tip_motion)
      {
        active_constraints = &fe_space->fixed_dofs;
        return;
      }
    const bool point = target.tip_motion->point_contact;
    if (!load.tip_motion || !prescribed_tip || prescribed_tip->point_contact() != point)
      anchor_tip_motion(point);
    active_constraints = &prescribed_tip->constraints();
  }

  // The tip moved to `state`'s motion, the body following linearly: with d
  // the tip DoFs' move, u += d + v where K v = -R(u) - K d on the free DoFs
  // (K and R at u, the tip held). Moving the tip DoFs alone shears the
  // elements at the tip face, and the first steps of a motion inverted them
  // until cut to a hundredth (docs/history.md, "A tip motion's first step").
  // K d is the directional derivative of the residual, by a forward
  // difference along d with step h = 1e-3 (relative error of order h times
  // the residual's curvature along d, well within Newton's tolerance: the
  // Newton iterations that follow correct it). Returns false if an element
  // inverts on the way (u is then as on entry).
  bool QuasiStaticSolver::predict_tip_motion(const LoadState &state)
  {
    TrilinosWrappers::MPI::Vector d(u_owned);
    prescribed_tip->apply(*state.tip_motion, d);
    d -= u_owned;
    constexpr double h = 1e-3;
    u_owned.add(h, d);
    u_ghosted     = u_owned;
    const bool ok = assemble(state, false);
    u_owned.add(-h, d);
    u_ghosted = u_owned;
    if (!ok)
      return false;
    TrilinosWrappers::MPI::Vector moved_rhs(rhs);
    if (!assemble(state, true))
      return false;
    // -R(u) - K d = rhs + (rhs(u + h d) - rhs) / h, rhs = -R (condensed).
    TrilinosWrappers::MPI::Vector b(rhs);
    b.sadd(1.0 - 1.0 / h, 1.0 / h, moved_rhs);
    if (motion_residual_scale == 0.0) // the residual the move alone would leave
      motion_residual_scale = b.l2_norm();
    if (!solve_tangent(b, du))
      return false;
    du += d;
    apply_update(du);
    return true;
  }

  QuasiStaticSolver::Result QuasiStaticSolver::solve(const LoadState &target)
  {
    return solve(target, prm.solver.initial_load_step);
  }

  // The straight load path from the solver's state at s = 0 to `target` at
  // s = 1. Each step starts from the extrapolation of the last converged
  // states (ContinuationPredictor: the secant, or the parabola through
  // three), which leaves Newton only the correction; a failed step returns
  // to the last converged state and its link states.
  // Measured on P10 (Q2 hex, 40 kPa from rest): a retry without the
  // predictor started from a residual of a few tenths of a newton with a
  // Newton update of 0.1-0.15 m and crept along it with line-search steps of
  // 0.1 for 5-7 iterations; with it, 1-2 iterations.
  class QuasiStaticSolver::StraightPath : public LoadPathProblem
  {
  public:
    StraightPath(QuasiStaticSolver &solver, const LoadState &target)
      : solver(solver)
      , start(solver.load)
      , target(target)
      , predictor(solver.u_owned)
      , links_converged(solver.link_states())
      , contact_converged(solver.contact ? solver.contact->history() : ObstacleContact::History())
      , pv{{start.pressure, solver.pressure->cavity_volume(solver.u_ghosted)}}
    {}

    NewtonSystem &begin_step(const double s) override
    {
      const LoadState state = LoadState::interpolate(start, target, s);
      const bool predicted = solver.prm.solver.secant_predictor && predictor.predict(s, solver.u_owned);
      // A prediction extrapolated from states where points were free may
      // carry them deep into an obstacle, where the penalty's force then
      // inverts elements in Newton's first step.
      if (predicted)
        solver.stop_at_contact(predictor.last(), solver.u_owned, state.obstacle_motion);
      solver.u_ghosted = solver.u_owned;
      // The tip where the motion puts it, held there by Newton; without
      // the path's history the body first follows it linearly.
      if (state.tip_motion && (predicted || !solver.predict_tip_motion(state)))
        {
          solver.prescribed_tip->apply(*state.tip_motion, solver.u_owned);
          solver.u_ghosted = solver.u_owned;
        }
      solver.aim_newton_at(state);
      augmentations = 0;
      return solver;
    }

    // Uzawa's update of the contact pressures where a converged state
    // penetrates deeper than Contact/Penetration tolerance, at most
    // Contact/Maximum augmentations times per step.
    bool augment() override
    {
      if (augmentations == solver.prm.contact.max_augmentations ||
          !solver.augment_contact(solver.newton_target.obstacle_motion))
        return false;
      ++augmentations;
      return true;
    }

    void accept_step(const double s) override
    {
      predictor.converged(s, solver.u_owned);
      solver.load     = solver.newton_target;
      links_converged = solver.link_states();
      contact_converged = solver.accept_contact_state(solver.load.obstacle_motion);
      pv.emplace_back(solver.load.pressure, solver.pressure->cavity_volume(solver.u_ghosted));
    }

    void reject_step() override
    {
      solver.restore(predictor.last(), links_converged);
      solver.restore_contact(contact_converged);
    }

    // (pressure, cavity volume) of the converged states, to tell a limit point.
    const std::vector<std::pair<double, double>> &pressure_volume() const { return pv; }

  private:
    QuasiStaticSolver                     &solver;
    const LoadState                        start;
    const LoadState                        target;
    ContinuationPredictor                  predictor;
    std::vector<TensionOnlyLaw::State>     links_converged;
    ObstacleContact::History               contact_converged; // multipliers and stick anchors
    unsigned int                           augmentations = 0;     // in this step
    std::vector<std::pair<double, double>> pv;
  };

  QuasiStaticSolver::Result QuasiStaticSolver::solve(const LoadState &target, const double first_step)
  {
    return solve(target, first_step, prm.solver.min_load_step);
  }

  QuasiStaticSolver::Result QuasiStaticSolver::solve(const LoadState &target, const double first_step,
                                                     const double min_step)
  {
    if (target.pressure != 0.0 && !pressure->has_cavity())
      throw data::InputError("a pressure of " + std::to_string(target.pressure) +
                             " Pa needs the mesh's physical group 'cavity'; this mesh has none");
    const auto start_time = std::chrono::steady_clock::now();
    prepare_tip_motion(target);
    Result       result;
    StraightPath problem(*this, target);
    const auto   path = LoadPath(prm, first_step, min_step, "load factor", log)
                           .follow(problem, &result.residual_history);
    result.converged           = path.finished();
    result.load_factor_reached = path.reached;
    result.newton_iterations   = path.newton_iterations;
    result.load_steps          = path.load_steps;
    if (!path.finished())
      classify_failure(problem.pressure_volume(), path, min_step, result);
    result.wall_time = seconds_since(start_time);
    return result;
  }

  // A pressure ramp that stalls while the pressure-volume curve flattens has
  // reached a limit point (balloon instability, dp/dV -> 0): a physical end
  // of pressure control, not a numerical failure.
  void QuasiStaticSolver::classify_failure(const std::vector<std::pair<double, double>> &pv,
                                           const LoadPath::Result &path, const double min_step,
                                           Result &result) const
  {
    std::ostringstream why;
    const double       p_last = pv.back().first;
    if (path.stop == LoadPath::Stop::too_many_attempts)
      {
        why << "gave up after " << path.attempts << " load step attempts (Solver/Maximum load "
            << "step attempts) at load factor " << path.reached << " (last converged pressure "
            << p_last << " Pa)";
        result.failure = Failure::too_many_attempts;
        result.reason  = why.str();
        return;
      }
    const bool inverted = path.last_failure == NewtonSolver::Status::inverted;
    if (pv.size() >= 3 && p_last != 0.0)
      {
        const auto   slope = [&](std::size_t k) {
          return (pv[k].first - pv[k - 1].first) / (pv[k].second - pv[k - 1].second);
        };
        const double ratio = slope(pv.size() - 1) / slope(1);
        if (std::isfinite(ratio) && ratio < 0.1)
          {
            why << "limit point at p = " << p_last << " Pa: dp/dV fell to " << 100 * ratio
                << "% of its initial value (the walls balloon; pressure control has no "
                   "equilibrium beyond it)";
            result.failure = Failure::limit_point;
            result.reason  = why.str();
            return;
          }
      }
    why << (inverted ? "elements inverted (J <= 0)" : "Newton did not converge")
        << " even with load steps below " << min_step << " (last converged pressure "
        << p_last << " Pa)";
    result.failure = inverted ? Failure::inverted : Failure::not_converged;
    result.reason  = why.str();
  }

  std::vector<Point<3>> QuasiStaticSolver::deformed_points(const std::vector<Point<3>> &points) const
  {
    return EmbeddedPoints(*fe_space, points, "force point").deformed(u_ghosted);
  }
} // namespace softchain::fem
