#pragma once
// VolumeControlledInflation: the cavity as a fluid cavity. Instead of the
// pressure p, the enclosed volume V is prescribed and p becomes an unknown:
//     R(u, p) = f_int(u) + f_springs(u) - p g(u) - f_other = 0,
//     V(u) - V_target = 0,
// where g = dV/du is the follower load of a unit pressure (p dV is the
// pressure's virtual work). Newton on the bordered system
//     [ K   -g ] [du]   [ -R           ]
//     [ g^T  0 ] [dp] = [ V_target - V ]
// is solved by the solver's configured linear solver, two solves of one
// factorisation of K (K a = -R, K b = g, dp = (V_target - V - g.a) / g.b,
// du = a + dp b); du is a Newton update of the solver's, springs' link
// states included. The bordered system is a NewtonSystem (NewtonSolver
// iterates on it, with the same tests and the halving of a step that
// inverts an element as pressure control) and the volume's path a
// LoadPathProblem (LoadPath steps along it). Each volume step starts from the extrapolated u and p
// with the links' states of the last converged step (their own Newton steps
// take them onward), and a failed step returns to that state, links and
// all, as pressure control does. The volume rises
// monotonically through a balloon limit point, where pressure control has no
// equilibrium beyond the peak (Crisfield, Non-linear Finite Element Analysis
// of Solids and Structures, Vol. 1, Sec. 9.5, displacement control as the
// simplest way past a load maximum).
#include <softchain/fem/continuation_predictor.h>
#include <softchain/fem/load_path.h>
#include <softchain/fem/newton_solver.h>
#include <softchain/fem/quasi_static_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace softchain::fem
{
  class VolumeControlledInflation : public NewtonSystem, public LoadPathProblem
  {
  public:
    struct PressureVolumePoint
    {
      double volume;   // m^3
      double pressure; // Pa
    };
    struct Result
    {
      bool                             converged = false;
      std::string                      reason; // why not
      unsigned int                     newton_iterations = 0;
      std::vector<PressureVolumePoint> curve; // every converged step, from the start
    };

    // Drives `solver` (its current state: at rest, or a converged state at
    // pressure `start_pressure`); no other loads are applied, and contact
    // obstacles stay where the start state has them.
    VolumeControlledInflation(QuasiStaticSolver &solver, const Parameters &prm,
                              double start_pressure = 0.0);

    double volume() const;
    double pressure() const { return p; }
    // g = dV/du: the nodal load of a unit follower pressure at the current state.
    dealii::TrilinosWrappers::MPI::Vector unit_pressure_load() const;

    // Inflates to `target_volume` in adaptive volume steps (AdaptiveLoadStepping),
    // each started from the extrapolation of u and p (ContinuationPredictor)
    // as under pressure control; leaves the solver at the last converged
    // state, with its load the pressure there.
    Result solve(double target_volume);

    // The bordered system at the volume of the current step.
    bool   assemble(bool with_matrix) override;
    double residual_norm() const override { return solver.residual_bound(); }
    // |R| <= tol |p g| and |V_target - V| <= Residual tolerance V_target.
    bool   residual_converged(double residual, double tolerance) const override;
    double solution_norm() const override { return solver.solution_norm(); }
    bool   solve_correction(bool same_tangent) override;
    bool   keeps_factorisation() const override { return solver.keeps_factorisation(); }
    double correction_norm() const override { return du.l2_norm(); }
    double correction_slope() const override { return -(du * solver.negative_residual()); }
    void   apply_correction() override;
    void   scale_correction(double factor) override;
    // The energy along du ignores the constraint: only a step that inverts
    // an element is shortened.
    bool   energy_line_search() const override { return false; }
    double admissible_fraction() override { return solver.admissible_fraction(du, obstacle_motion); }

    // The volume path's steps.
    NewtonSystem &begin_step(double s) override;
    void          accept_step(double s) override;
    void          reject_step() override;
    bool          augment() override; // the contact's Uzawa updates

  private:
    QuasiStaticSolver &solver;
    const Parameters  &prm;
    double             p;
    double             obstacle_motion; // the obstacles stay where the start state has them
    // The path of the current solve(): its start, the volume aimed at, the
    // converged states and the bordered system's unknowns.
    double                                v_start = 0, v_end = 0, v_target = 0;
    std::unique_ptr<ContinuationPredictor> predictor;
    std::vector<TensionOnlyLaw::State>    links_converged;
    ObstacleContact::History              contact_converged;
    unsigned int                          augmentations = 0; // in the current step
    std::vector<PressureVolumePoint>     *curve = nullptr;
    dealii::TrilinosWrappers::MPI::Vector g;  // dV/du at the iterate
    double                                misfit = 0; // V_target - V at the iterate
    dealii::TrilinosWrappers::MPI::Vector du; // the bordered step's displacement ...
    double                                dp = 0; // ... and pressure

    dealii::TrilinosWrappers::MPI::Vector owned_displacement() const;
    LoadState                             pressure_state() const; // the load p alone
  };
} // namespace softchain::fem
