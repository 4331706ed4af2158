#pragma once
// ContinuationPredictor: where a load step of a path s in [0, 1] starts
// Newton, extrapolated from the path's last converged states (u_k at s_k,
// newest first). With two states it is the secant
//     u(s) = u_0 + (s - s_0) / (s_0 - s_1) (u_0 - u_1),
// with three the parabola through them (Lagrange), whose error is of one
// order higher in the step where the path is smooth, and larger where its
// curvature changes fast (the first steps from rest, a snap). So the order
// is chosen as variable-order ODE integrators choose theirs: from a fourth
// state on, the parabola is used for the next step only if, through u_1..u_3,
// it would have predicted u_0 closer than the secant through u_1, u_2 did.
// Measured on P10 from rest to 40 kPa (Q2 hexahedra, 5.5 mm): 58 Newton
// iterations in 10 load steps against 73 in 15 with the secant alone
// (docs/history.md, "A second-order predictor"). A scalar unknown of the
// path (volume control's pressure) is carried along with u.
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace softchain::fem
{
  class ContinuationPredictor
  {
  public:
    // The path's start: the converged state (u, scalar) at s = 0.
    explicit ContinuationPredictor(const dealii::TrilinosWrappers::MPI::Vector &u, double scalar = 0);

    // The load step to s converged at (u, scalar).
    void converged(double s, const dealii::TrilinosWrappers::MPI::Vector &u, double scalar = 0);
    // The last converged state (where a failed step is retried from).
    const dealii::TrilinosWrappers::MPI::Vector &last() const { return states.front().u; }

    // u (and the scalar, if given) extrapolated to s; false (both unchanged)
    // before the first step has converged (one state: nothing to
    // extrapolate from).
    bool predict(double s, dealii::TrilinosWrappers::MPI::Vector &u, double *scalar = nullptr) const;
    // 1 (secant) or 2 (parabola): the order predict() uses.
    unsigned int order() const { return quadratic ? 2 : 1; }

  private:
    struct State
    {
      double                                s;
      dealii::TrilinosWrappers::MPI::Vector u;
      double                                scalar;
    };
    std::vector<State> states; // newest first, at most four
    bool               quadratic = false;

    // The Lagrange polynomial through states[first], ..., states[first +
    // n - 1], evaluated at s; returns the scalar's.
    double extrapolate(unsigned int first, unsigned int n, double s,
                       dealii::TrilinosWrappers::MPI::Vector &u) const;
  };
} // namespace softchain::fem
