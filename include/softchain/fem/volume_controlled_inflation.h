#pragma once
// VolumeControlledInflation: the cavity as a fluid cavity. Instead of the
// pressure p, the enclosed volume V is prescribed and p becomes an unknown
// (BorderedLoadControl with mu = p, c = V and q = dV/du = g, the follower
// load of a unit pressure: p dV is the pressure's virtual work). No other
// loads are applied. The volume rises monotonically through a balloon limit
// point, where pressure control has no equilibrium beyond the peak.
#include <softchain/fem/bordered_load_control.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  class VolumeControlledInflation : public BorderedLoadControl
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
    // pressure `start_pressure`); contact obstacles stay where the start
    // state has them.
    VolumeControlledInflation(QuasiStaticSolver &solver, const Parameters &prm,
                              double start_pressure = 0.0);

    double volume() const { return conjugate_displacement(); }
    double pressure() const { return load_amount(); }
    // V(u), the cavity's volume.
    double conjugate_displacement() const override;
    // g = dV/du: the nodal load of a unit follower pressure at the current state.
    dealii::TrilinosWrappers::MPI::Vector unit_load() const override;

    // Inflates to `target_volume` in adaptive volume steps (AdaptiveLoadStepping),
    // each started from the extrapolation of u and p (ContinuationPredictor)
    // as under pressure control; leaves the solver at the last converged
    // state, with its load the pressure there.
    Result solve(double target_volume);

  private:
    LoadState load_at(double p) const override; // the pressure p alone
  };
} // namespace softchain::fem
