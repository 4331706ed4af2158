#pragma once
// BorderedLoadControl: displacement control of one load. The load's amount
// mu (a cavity pressure [Pa], a force magnitude [N]) becomes an unknown, and
// the displacement work-conjugate to it is prescribed instead:
//     R(u, mu) = f_int(u) + f_springs(u) - f_ext(u, mu) = 0,
//     c(u) - c_target = 0,
// where q = df_ext/dmu is the nodal load of a unit amount and c the
// displacement it works on, dc/du = q (the cavity's volume for a follower
// pressure, the force points' displacement along a dead force). Newton on
// the bordered system
//     [ K   -q ] [du ]   [ -R                ]
//     [ q^T  0 ] [dmu] = [ c_target - c(u)   ]
// is solved by the solver's configured linear solver, two solves of one
// factorisation of K (K a = -R, K b = q, dmu = (c_target - c - q.a) / q.b,
// du = a + dmu b); du is a Newton update of the solver's, springs' link
// states included. K may be singular at a limit point of the load; the
// bordered matrix is not. The control rises monotonically through a limit
// point, where load control has no equilibrium beyond the peak (Crisfield,
// Non-linear Finite Element Analysis of Solids and Structures, Vol. 1, Sec.
// 9.5, displacement control as the simplest way past a load maximum).
//
// The bordered system is a NewtonSystem (NewtonSolver iterates on it, with
// the same tests and the halving of a step that inverts an element as load
// control) and the control's path a LoadPathProblem (LoadPath steps along
// it). Each step starts from the extrapolated u and mu with the links'
// states of the last converged step (their own Newton steps take them
// onward), and a failed step returns to that state, links and contact
// included. What the load is, is the subclass's business:
// VolumeControlledInflation (a pressure, c the volume) and
// DisplacementControlledForces (point forces, c their points' displacement).
#include <softchain/fem/continuation_predictor.h>
#include <softchain/fem/load_path.h>
#include <softchain/fem/newton_solver.h>
#include <softchain/fem/quasi_static_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace softchain::fem
{
  class BorderedLoadControl : public NewtonSystem, public LoadPathProblem
  {
  public:
    // A converged state of the path.
    struct PathPoint
    {
      double displacement; // c
      double load;         // mu
    };
    struct Path
    {
      LoadPath::Result       steps;
      std::vector<PathPoint> points; // every converged step, from the start
    };

    // The load's amount at the current iterate.
    double load_amount() const { return mu; }
    // c(u) at the solver's current displacement.
    virtual double conjugate_displacement() const = 0;
    // q = df_ext/dmu = dc/du at the solver's current displacement.
    virtual dealii::TrilinosWrappers::MPI::Vector unit_load() const = 0;

    // The bordered system at the current step's c_target.
    bool   assemble(bool with_matrix) override;
    double residual_norm() const override { return solver.residual_bound(); }
    // The solver's residual test (|R| against the external loads) and
    // |c_target - c| <= Residual tolerance times the path's scale of c.
    bool   residual_converged(double residual, double tolerance) const override;
    double residual_scale() const override { return solver.residual_scale(); }
    double solution_norm() const override { return solver.solution_norm(); }
    bool   solve_correction(bool same_tangent, double forcing) override;
    bool   keeps_factorisation() const override { return solver.keeps_factorisation(); }
    double correction_norm() const override { return du.l2_norm(); }
    double correction_slope() const override { return -(du * solver.negative_residual()); }
    void   apply_correction() override;
    void   scale_correction(double factor) override;
    // The energy along du ignores the constraint: only a step that inverts
    // an element is shortened.
    bool   energy_line_search() const override { return false; }
    bool   backtrack_when_stalled() const override { return solver.backtrack_when_stalled(); }
    double admissible_fraction() override { return solver.admissible_fraction(du, obstacle_motion); }

    // The control's path steps.
    NewtonSystem &begin_step(double s) override;
    void          accept_step(double s) override;
    void          reject_step() override;
    bool          augment() override; // the contact's Uzawa updates

  protected:
    // Drives `solver` from its current state (rest, or a converged state at
    // the load amount `start_load`); contact obstacles stay where the start
    // state has them.
    BorderedLoadControl(QuasiStaticSolver &solver, const Parameters &prm, double start_load);

    // The loads at amount mu (the obstacles' place is the base's).
    virtual LoadState load_at(double mu) const = 0;

    // Follows c linearly from its value now (s = 0) to `c_end` (s = 1) in
    // adaptive steps of s, the first `first_step`; `name` names s in the
    // log. Leaves the solver at the last converged state, with its loads.
    Path follow(double c_end, double first_step, const std::string &name);

    QuasiStaticSolver &solver;
    const Parameters  &prm;

  private:
    double mu;
    double obstacle_motion; // the obstacles stay where the start state has them
    // The path of the current follow(): its start and end, the current
    // step's target, the converged states and the bordered system's unknowns.
    double                                 c_start = 0, c_end = 0, c_target = 0;
    std::unique_ptr<ContinuationPredictor> predictor;
    std::vector<TensionOnlyLaw::State>     links_converged;
    ObstacleContact::History               contact_converged;
    unsigned int                           augmentations = 0; // in the current step
    std::vector<PathPoint>                *points = nullptr;
    dealii::TrilinosWrappers::MPI::Vector  q;  // dc/du at the iterate
    double                                 misfit = 0; // c_target - c at the iterate
    dealii::TrilinosWrappers::MPI::Vector  du; // the bordered step's displacement ...
    double                                 dmu = 0; // ... and load amount

    LoadState loads() const; // load_at(mu), the obstacles where the start has them
  };
} // namespace softchain::fem
