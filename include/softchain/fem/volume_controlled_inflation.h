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
// states included. Each volume step starts from the extrapolated u and p
// with the links' states of the last converged step (their own Newton steps
// take them onward), and a failed step returns to that state, links and
// all, as pressure control does. The volume rises
// monotonically through a balloon limit point, where pressure control has no
// equilibrium beyond the peak (Crisfield, Non-linear Finite Element Analysis
// of Solids and Structures, Vol. 1, Sec. 9.5, displacement control as the
// simplest way past a load maximum).
#include <softchain/fem/quasi_static_solver.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  class VolumeControlledInflation
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
    // pressure `start_pressure`); no other loads are applied.
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

  private:
    QuasiStaticSolver &solver;
    const Parameters  &prm;
    double             p;

    // Newton at a fixed volume, to the final tolerances if `final_state`,
    // else to the intermediate one (a stepping stone); false if it fails
    // (state restored by the caller).
    bool newton(double target_volume, Result &result, bool final_state);
    dealii::TrilinosWrappers::MPI::Vector owned_displacement() const;
    LoadState                             pressure_state() const; // the load p alone
  };
} // namespace softchain::fem
