#pragma once
// NewtonSolver: Newton-Raphson on a nonlinear system R(x) = 0 that a
// NewtonSystem assembles, MFEM's split of an operator and the solver that
// iterates on it. The iterations, the line search, the two convergence
// tests and the classification of a failure live here, once; a system knows
// its residual, its tangent, its linear solve and how a step moves its state.
// Pressure control, prescribed motion (QuasiStaticSolver) and volume control
// (VolumeControlledInflation, a bordered system) are such systems.
//
// One iteration, from x_k:
//  1. assemble -R(x_k) and K = dR/dx; an element with J <= 0 makes x_k
//     invalid: it is halved back towards x_{k-1} (line search);
//  2. converged when |R| <= tol_R * scale and the error |x* - x_k| <= tol_x |x|,
//     the error bounded by the last update or estimated by the simplified
//     Newton correction K(x_{k-1})^-1 R(x_k) from kept factors (Deuflhard,
//     Newton Methods for Nonlinear Problems, 2004, Sec. 2.1, NLEQ-ERR);
//  3. dx = -K^-1 R, solved to a linear residual eta_k |R| (an inexact
//     Newton step, Dembo, Eisenstat and Steihaug, SIAM J. Numer. Anal. 19,
//     1982: it converges as Newton's up to a term eta_k |R|; forcing()),
//     x_{k+1} = x_k + a dx, a = 1 unless the system admits
//     less of it (contact points entering an obstacle) or the line search on
//     the energy's slope s(a) = dx . R(x_k + a dx) cuts it (Crisfield,
//     Non-linear Finite Element Analysis of Solids and Structures, Vol. 1,
//     Sec. 9.3).
#include <softchain/fem/parameters.h>

#include <ostream>
#include <vector>

namespace softchain::fem
{
  // What Newton needs of a system; the state x, the correction dx and the
  // assembled residual live in the system.
  class NewtonSystem
  {
  public:
    virtual ~NewtonSystem() = default;
    // Assembles -R (and with `with_matrix` the tangent K) at the current x.
    // False if some quadrature point has J <= 0.
    virtual bool   assemble(bool with_matrix) = 0;
    // The residual's norm as the convergence test measures it.
    virtual double residual_norm() const = 0;
    // Called once per Newton solve with the first valid residual.
    virtual void   first_residual(double /*residual*/) {}
    // |R| <= tolerance times the system's residual scale (its loads).
    virtual bool   residual_converged(double residual, double tolerance) const = 0;
    // That scale.
    virtual double residual_scale() const = 0;
    // |x|, the error test's scale.
    virtual double solution_norm() const = 0;
    // dx = -K^-1 R with the last assembled K, to a linear residual |K dx +
    // R| <= forcing |R| where the linear solver is iterative (exactly by a
    // direct one); `same_tangent`: with the factors of the last solve where
    // the linear solver keeps them. False if the linear solve failed (a
    // singular K, a Krylov solve that stalled).
    virtual bool   solve_correction(bool same_tangent, double forcing) = 0;
    virtual bool   keeps_factorisation() const = 0;
    virtual double correction_norm() const = 0;
    // dx . R at the current x: the energy's slope along dx (< 0 before a
    // step, for a positive definite K).
    virtual double correction_slope() const = 0;
    // x += dx (x_old = x before it).
    virtual void   apply_correction() = 0;
    // Shortens the last correction: x = x_old + factor (x - x_old), dx *= factor.
    virtual void   scale_correction(double factor) = 0;
    // The fraction of the correction dx the system lets Newton take (1: all
    // of it): a step that carries contact points deep into an obstacle is
    // stopped where they enter (ObstacleContact::entry_fraction).
    virtual double admissible_fraction() { return 1.0; }
    // Whether the energy line search applies (else only a step that inverts
    // an element is shortened).
    virtual bool   energy_line_search() const = 0;
    // Whether a stalled Newton shortens its steps until |R| falls
    // (NewtonSolver::backtrack): where friction switches points between
    // stick and slip, full steps can cycle.
    virtual bool   backtrack_when_stalled() const = 0;
  };

  class NewtonSolver
  {
  public:
    enum class Status
    {
      converged,
      inverted,       // elements inverted (J <= 0) in the step
      linear_failure, // the linear solve failed
      not_finite,     // the residual is not a finite number
      not_converged   // Maximum Newton iterations reached
    };
    struct Outcome
    {
      Status       status;
      unsigned int iterations;
      bool         converged() const { return status == Status::converged; }
    };

    // Keeps a copy of `prm` (a small struct of numbers), so that a solver
    // made from a temporary stays valid.
    NewtonSolver(const SolverParameters &prm, bool verbose, std::ostream &log);

    // Iterates on `system` from its current x. `final_state`: to Residual
    // and Displacement tolerance, else to Intermediate tolerance (a load
    // step short of the path's end). Appends every iterate's |R| to `history`.
    Outcome solve(NewtonSystem &system, bool final_state, std::vector<double> *history = nullptr);

  private:
    const SolverParameters prm;
    const bool             verbose;
    std::ostream          &log;

    // After x = x_old + dx: keeps the full step where |s(1)| <= 0.8 |s(0)|,
    // else goes to the secant's zero of s within [0.1, 1]; a step that
    // inverts an element (`valid` false) is halved, at most six times.
    // Returns whether an admissible x was found (assembled, K included).
    bool line_search(NewtonSystem &system, double s0, bool valid);
    // After a step taken where Newton had stalled: halves it, at most four
    // times, until |R| falls below `before` (the residual it started from),
    // and keeps the step of the smallest |R| (assembled, K included).
    // Returns that |R|.
    double backtrack(NewtonSystem &system, double residual, double before);
    static bool stalled(const std::vector<double> &residuals);
    // The forcing term eta of the correction at residual |R| in the path's
    // last step (`final_state`) or a stepping stone.
    double forcing(const NewtonSystem &system, double residual, bool final_state) const;
  };
} // namespace softchain::fem
