#pragma once
// QuasiStaticSolver: total-Lagrangian, quasi-static, large-deformation
// equilibrium of a hyperelastic body with a follower cavity pressure,
// embedded tension-only springs and point loads:
//     R(u) = f_int(u) + f_springs(u) - f_pressure(u) - f_points = 0,
// the operator of a NewtonSolver (residual, exact tangent K = dR/du, linear
// solve), driven along a straight load path in adaptive steps (LoadPath).
// The line search is on the energy without springs; with them, a step that
// inverts an element is halved. The cells (HyperelasticCell) and the springs inside
// them are assembled together, cell by cell; the springs' tensions are
// Newton unknowns of their own, condensed per link (EmbeddedSpringNetwork).
#include <softchain/fem/cell_matrix_scatter.h>
#include <softchain/fem/dead_surface_traction.h>
#include <softchain/fem/embedded_points.h>
#include <softchain/fem/embedded_spring_network.h>
#include <softchain/fem/finite_element_space.h>
#include <softchain/fem/follower_pressure.h>
#include <softchain/fem/hyperelastic_material.h>
#include <softchain/fem/load_path.h>
#include <softchain/fem/load_state.h>
#include <softchain/fem/newton_solver.h>
#include <softchain/fem/obstacle_contact.h>
#include <softchain/fem/parameters.h>
#include <softchain/fem/prescribed_tip.h>
#include <softchain/fem/tangent_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace softchain::fem
{
  class QuasiStaticSolver : public NewtonSystem
  {
  public:
    // Why a solve stopped short of its target.
    enum class Failure
    {
      none,
      not_converged, // Newton failed even at the smallest load step
      inverted,      // elements inverted (J <= 0) even at the smallest load step
      limit_point,   // pressure control passed a physical limit point (dp/dV -> 0)
      too_many_attempts // Solver/Maximum load step attempts used up
    };

    struct Result
    {
      bool                converged = false;
      Failure             failure   = Failure::none;
      std::string         reason; // why not converged, for people
      double              load_factor_reached = 0.0;
      unsigned int        newton_iterations   = 0;
      unsigned int        load_steps          = 0;
      double              wall_time           = 0.0;
      std::vector<double> residual_history; // |R| of every Newton iteration
    };

    // `material_names[id]` names the .prm material region of material id.
    QuasiStaticSolver(const Parameters                  &parameters,
                      const dealii::Triangulation<3>            &serial_mesh,
                      const std::vector<std::string>    &material_names,
                      const std::vector<SpringPolyline> &springs,
                      const std::vector<FibreSheet>     &sheets,
                      MPI_Comm                           communicator,
                      std::ostream                      &log);

    // Moves the current state (rest, or the last converged state) to
    // `target` along the straight load path between them, the first load
    // step `first_step` of the path (default: Solver/Initial load step),
    // given up once a cut step falls below `min_step` (default: Solver/
    // Minimum load step).
    Result solve(const LoadState &target);
    Result solve(const LoadState &target, double first_step);
    Result solve(const LoadState &target, double first_step, double min_step);
    // Back to the undeformed state with no load.
    void reset();

    // The pieces, for tests and output.
    const FiniteElementSpace            &space() const { return *fe_space; }
    const dealii::TrilinosWrappers::MPI::Vector &displacement() const { return u_ghosted; }
    // The same without ghosts (this rank's DoFs), for dot products and copies.
    const dealii::TrilinosWrappers::MPI::Vector &owned_displacement() const { return u_owned; }
    void set_displacement(const dealii::TrilinosWrappers::MPI::Vector &owned_u);
    // u = owned_u with the springs' link states (their tensions and gaps,
    // Newton unknowns) kept as they are: a predictor's start, from which the
    // links take their own Newton steps as under pressure control.
    void move_to(const dealii::TrilinosWrappers::MPI::Vector &owned_u);
    // The springs' link states, to return to with a converged state after a
    // step that failed (empty without springs).
    std::vector<TensionOnlyLaw::State> link_states() const;
    // Back to a converged state: u = owned_u and the link states it had.
    void restore(const dealii::TrilinosWrappers::MPI::Vector &owned_u,
                 const std::vector<TensionOnlyLaw::State>    &links);
    // The loads of the current state (rest, or the last converged load step).
    const LoadState &load_state() const { return load; }
    // Restart from a stored equilibrium: `owned_u` balances `state` (the
    // next solve() continues from there; used by the sample sweep).
    void set_state(const dealii::TrilinosWrappers::MPI::Vector &owned_u, const LoadState &state)
    {
      set_displacement(owned_u);
      load = state;
    }
    // Takes the current state as the one that later tip motions (of the
    // given kind: face held or point contact) are relative to
    // (PrescribedTip::anchor); a solve from a state without tip motion
    // anchors there by itself, a restart from a moved state needs this first.
    void anchor_tip_motion(bool point_contact);
    // Assembles rhs = -R(u) (and K = dR/du when with_matrix) at `state`.
    // Returns false if some quadrature point has J <= 0.
    bool assemble(const LoadState &state, bool with_matrix);
    // rhs = f_ext - f_int at the current state with no Dirichlet constraint:
    // at the clamped DoFs it then holds the forces the finger exerts on its
    // supports (BaseReaction), elsewhere the equilibrium residual.
    const dealii::TrilinosWrappers::MPI::Vector &support_forces();
    const dealii::TrilinosWrappers::SparseMatrix &tangent() const { return matrix; }
    const dealii::TrilinosWrappers::MPI::Vector  &negative_residual() const { return rhs; }
    // |R| + a bound on how far the assembled residual lies from the
    // tension law's (the springs' link states are Newton iterates): the
    // residual norm the convergence tests use.
    double residual_bound() const;
    // x = K^-1 b by the configured linear solver, K the tangent of the last
    // assemble(), x with the active constraints; `same_tangent`: with the
    // factorisation of the last call where the solver keeps one
    // (keeps_factorisation()), even if K was assembled anew since, else with
    // K. False if the solver failed (a singular K, a Krylov solve that did
    // not converge).
    // `forcing`: the relative residual |b - K x| <= forcing |b| an iterative
    // solve may stop at (0: the solver's own tolerance).
    bool solve_tangent(const dealii::TrilinosWrappers::MPI::Vector &b,
                       dealii::TrilinosWrappers::MPI::Vector       &x,
                       bool                                         same_tangent = false,
                       double                                       forcing      = 0);
    // A Newton update: u += update, and the springs' link states take their
    // Newton step for it; scale_correction() shortens it.
    void apply_update(const dealii::TrilinosWrappers::MPI::Vector &update);

    // The NewtonSystem at the load state set by aim_newton_at().
    void   aim_newton_at(const LoadState &state) { newton_target = state; }
    bool   assemble(bool with_matrix) override { return assemble(newton_target, with_matrix); }
    double residual_norm() const override { return residual_bound(); }
    void   first_residual(double residual) override;
    bool   residual_converged(double residual, double tolerance) const override;
    double residual_scale() const override;
    double solution_norm() const override { return u_owned.l2_norm(); }
    bool   solve_correction(bool same_tangent, double forcing) override
    {
      return solve_tangent(rhs, du, same_tangent, forcing);
    }
    bool   keeps_factorisation() const override;
    double correction_norm() const override { return du.l2_norm(); }
    double correction_slope() const override { return -(du * rhs); }
    void   apply_correction() override { apply_update(du); }
    void   scale_correction(double factor) override;
    // The fraction of du along which no contact point that no obstacle
    // presses enters one deeper than 2 % of its face's size
    // (ObstacleContact::entry_fraction; 1 without contact).
    double admissible_fraction() override;
    // The same for the step u += step, the obstacles moved by `motion`.
    double admissible_fraction(const dealii::TrilinosWrappers::MPI::Vector &step, double motion);
    // Shortens the step from the owned state `from` to `to` (a prediction)
    // the same way: to = from + a (to - from); returns a.
    double stop_at_contact(const dealii::TrilinosWrappers::MPI::Vector &from,
                           dealii::TrilinosWrappers::MPI::Vector &to, double motion);
    // With springs the energy criterion is left out: their tensions are
    // Newton unknowns whose own step the energy along du ignores, and it
    // cut good steps to a tenth (the demo's sweep: 1917 against 1519
    // Newton iterations); without springs it pays (the CalculiX bender,
    // Q2 at 3 kPa in one step: 10 against 16). docs/history.md, "Link
    // tensions as Newton unknowns". Friction has no energy either.
    bool   energy_line_search() const override
    {
      return !springs && !(contact && contact->has_friction());
    }
    // Only with friction: elsewhere a stalled Newton (at a limit point, say)
    // is better cut short by a shorter load step (the demo's sweep took 1405
    // instead of 1327 Newton iterations with backtracking everywhere, its
    // sideways buckling 181 instead of 111).
    bool   backtrack_when_stalled() const override { return contact && contact->has_friction(); }
    const FollowerPressure              &pressure_load() const { return *pressure; }
    // The nodal load of dead `point_loads` at their reference points, zero
    // at the constrained DoFs (displacement control's unit load).
    dealii::TrilinosWrappers::MPI::Vector point_load_vector(const std::vector<PointLoad> &point_loads) const;
    // The contact with the obstacles of subsection Contact (none: nullptr).
    const ObstacleContact               *obstacle_contact() const { return contact.get(); }
    // Puts the obstacles of `scene` in the following solves, with a fresh
    // contact history (no obstacles: no contact). The solver starts with
    // subsection Contact's scene; the sample sweep sets each contact
    // sample's own.
    void                                 set_contact(const geometry::ContactScene &scene);
    // The current state, with the obstacles moved by `obstacle_motion`, is
    // a converged one: the contact's stick anchors follow it
    // (ObstacleContact::commit). Returns the contact's history there, to
    // return to with restore_contact() after a failed step.
    ObstacleContact::History             accept_contact_state(double obstacle_motion);
    void                                 restore_contact(const ObstacleContact::History &history);
    // Uzawa's update of the contact pressures at the current state
    // (ObstacleContact::augment); false without contact.
    bool                                 augment_contact(double obstacle_motion);
    const EmbeddedSpringNetwork         *spring_network() const { return springs.get(); }
    const HyperelasticMaterial &material(dealii::types::material_id id) const { return *materials.at(id); }
    // Deformed positions of `points` (reference, inside the body).
    std::vector<dealii::Point<3>> deformed_points(const std::vector<dealii::Point<3>> &points) const;
    dealii::TimerOutput          &timer() { return computing_timer; }
    // The solver's log (Output/Verbose: Newton's iterations and load steps).
    std::ostream                 &log_stream() const { return log; }

  private:
    // The fraction a of the step from `from` to `to` (owned states) that the
    // contact admits (ObstacleContact::entry_fraction).
    double contact_entry_fraction(const dealii::TrilinosWrappers::MPI::Vector &from,
                                  const dealii::TrilinosWrappers::MPI::Vector &to, double motion);
    const Parameters                                   &prm;
    std::ostream                                       &log;
    std::unique_ptr<FiniteElementSpace>                 fe_space;
    std::vector<std::unique_ptr<HyperelasticMaterial>> materials;
    std::unique_ptr<FollowerPressure>                   pressure;
    std::unique_ptr<DeadSurfaceTraction>                tip_traction;
    std::unique_ptr<EmbeddedSpringNetwork>              springs;
    std::unique_ptr<ObstacleContact>                    contact;
    std::vector<double>                                 youngs_moduli; // per material, for the contact's penalty
    dealii::TimerOutput                                         computing_timer;
    std::unique_ptr<TangentSolver>                      tangent_solver; // TangentSolver::create()
    // The cells' places in `matrix` for fe_space->fixed_dofs on one rank.
    std::unique_ptr<CellMatrixScatter>                  scatter;
    std::unique_ptr<PrescribedTip>                      prescribed_tip; // built at the first tip motion
    // fe_space->fixed_dofs, or those and the tip DoFs while a tip motion is prescribed.
    const dealii::AffineConstraints<double>            *active_constraints = nullptr;
    // Residual scale of a solve whose loads may all be prescribed motion
    // (f_ext = 0): the residual right after the first step moved the tip.
    double                                              motion_residual_scale = 0.0;
    bool pattern_couples_tip = false; // the matrix can hold a point contact's couplings

    dealii::TrilinosWrappers::SparseMatrix matrix;
    // With friction, the part of `matrix` that makes it unsymmetric
    // (ObstacleContact::assemble), for the linear solver; empty otherwise.
    dealii::TrilinosWrappers::SparseMatrix friction_unsymmetric_part;
    dealii::TrilinosWrappers::MPI::Vector  rhs;       // writable ghosts
    dealii::TrilinosWrappers::MPI::Vector  u_owned;   // the displacement
    dealii::TrilinosWrappers::MPI::Vector  u_ghosted; // same, with ghost values
    dealii::TrilinosWrappers::MPI::Vector  du;
    dealii::TrilinosWrappers::MPI::Vector  du_ghosted; // for the links' updates
    dealii::TrilinosWrappers::MPI::Vector  from_ghosted, to_ghosted; // a step's ends, for contact
    dealii::IndexSet                       writable_dofs;
    LoadState                      load; // at u
    double                         f_ext_norm = 0.0;
    // Bound on |R_law - R_assembled| from the links' condensed tensions
    // (EmbeddedSpringNetwork::assemble_cell).
    double                         tension_mismatch = 0.0;

    void setup_system();
    void setup_matrix(const dealii::AffineConstraints<double> &constraints,
                      const dealii::IndexSet                  &coupled);
    bool assemble_with(const LoadState &state, bool with_matrix,
                       const dealii::AffineConstraints<double> &constraints);
    bool assemble_cells(bool with_matrix, double gravity_factor,
                        const dealii::AffineConstraints<double> &constraints);
    // Do cell sums under `constraints` go through `scatter`'s places?
    bool by_places(const dealii::AffineConstraints<double> &constraints) const;
    void assemble_point_loads(const std::vector<PointLoad>            &point_loads,
                              const dealii::AffineConstraints<double> &constraints,
                              dealii::TrilinosWrappers::MPI::Vector   &vector) const;
    LoadState                      newton_target; // the state Newton iterates towards
    double                         correction_taken = 1.0; // of the last Newton update (line search)

    // The straight load path from the current state to a target (a
    // LoadPathProblem).
    class StraightPath;
    void          prepare_tip_motion(const LoadState &target);
    bool          predict_tip_motion(const LoadState &state);
    // Sets result.failure and result.reason of a solve that stalled.
    void          classify_failure(const std::vector<std::pair<double, double>> &pv,
                                   const LoadPath::Result &path, double min_step, Result &result) const;
  };
} // namespace softchain::fem
