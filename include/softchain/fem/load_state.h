#pragma once
// LoadState: the actuation applied at one instant of a load path, S = (p,
// point loads), as in the paper's actuation samples (Sec. III-A). A load step
// moves linearly from a start state to a target state, so a sample can start
// from rest or from a converged neighbour (continuation).
#include <softchain/fem/parameters.h>
#include <softchain/fem/prescribed_tip.h>

#include <optional>
#include <vector>

namespace softchain::fem
{
  struct LoadState
  {
    double                 pressure = 0.0;
    std::vector<PointLoad> point_loads;
    double                 gravity_factor = 0.0; // 1: full gravity
    dealii::Tensor<1, 3>           tip_traction;         // dead traction on `tip`, N/m^2
    // A rigid motion of the tip face (PrescribedTip) instead of a free tip.
    std::optional<TipMotion> tip_motion;
    // How far the contact obstacles have moved along their Motion
    // (ContactScene): 0 at rest, 1 the whole translation.
    double                 obstacle_motion = 0.0;

    // (1 - s) * start + s * target, the point loads matched by position; a
    // tip motion blends from the start's (none: at rest) to the target's, and
    // exists only if the target has one (a target without releases the tip).
    static LoadState interpolate(const LoadState &start, const LoadState &target, double s);
  };
} // namespace softchain::fem
