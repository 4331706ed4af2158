#pragma once
// DisplacementControlledForces: point forces past a limit point. From a
// converged state under loads S_0 (the pressure p, forces f_0 at points
// X_k) the forces move towards a target S_1 (the same pressure, forces f_1):
//     f(mu) = f_0 + (mu / F) (f_1 - f_0),    F = (sum_k |f_1k - f_0k|^2)^(1/2),
// mu in newtons from 0 to F. Under force control a sideways buckling of the
// finger is a limit point of mu: beyond its peak there is no equilibrium
// nearby, and the path stops. Here mu is an unknown and the forces'
// conjugate displacement is prescribed (BorderedLoadControl):
//     c(u) = q . u,   q the nodal load of (f_1 - f_0) / F,
// for one force the displacement of its point along the force. c rises in
// adaptive steps, through the peak of mu and the drop after it, until mu
// reaches F; the state there, on the branch past the buckling, is brought to
// mu = F exactly by load control (mu rose through F, so that branch is stable
// against the forces there).
//
// c ends at most the body's diagonal beyond its start (no point moves
// further than the body's size along a fixed direction in any deformation
// that keeps the finger whole); the first step is the initial load step of
// the linear estimate of c's increment, F q . K^-1 q.
#include <softchain/fem/bordered_load_control.h>

#include <optional>
#include <string>
#include <vector>

namespace softchain::fem
{
  class DisplacementControlledForces : public BorderedLoadControl
  {
  public:
    struct Result
    {
      bool         converged = false;
      std::string  reason; // why not
      unsigned int newton_iterations = 0;
      unsigned int load_steps        = 0;
      // Where the forces passed a limit point (mu fell from one step to the
      // next): the peak's mu / F, and the forces' magnitude there [N] (the
      // root sum of squares over the points, the start's forces included);
      // none on a path without one.
      std::optional<double> limit_fraction, limit_force;
      std::vector<PathPoint> path; // (c [m], mu [N]) of every converged step
      // mu / F of the state the solver is left at (1 when converged).
      double reached_fraction = 0;
    };

    // Whether `start` (the solver's converged state) and `target` differ only
    // in their point forces, as this control needs.
    static bool applies(const LoadState &start, const LoadState &target);

    // From the solver's current converged state (its load_state()) towards
    // `target`.
    DisplacementControlledForces(QuasiStaticSolver &solver, const Parameters &prm,
                                 const LoadState &target);

    double conjugate_displacement() const override { return q * solver.owned_displacement(); }
    dealii::TrilinosWrappers::MPI::Vector unit_load() const override { return q; }

    // Leaves the solver at the target's equilibrium, or at the last
    // converged state with its loads.
    Result solve();

    bool goal_reached() const override { return load_amount() >= force_increment; }

  private:
    const LoadState                       start, target;
    const std::vector<PointLoad>          increment;       // f_1 - f_0 per point
    const double                          force_increment; // F
    const dealii::TrilinosWrappers::MPI::Vector q;

    LoadState load_at(double mu) const override;
    // The first step of the path parameter for a path of length `span`.
    double first_step(double span);
  };
} // namespace softchain::fem
