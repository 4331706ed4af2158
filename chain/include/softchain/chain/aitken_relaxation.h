#pragma once
// AitkenRelaxation: the normal forces of a frictional load step's next
// solve (FrictionalLoadPath) from the lagged ones N_k it was solved with
// and those N(N_k) it found. Aitken's dynamic relaxation (Irons and Tuck
// 1969; Kuettler and Wall 2008, Comput. Mech. 43, 61): with the residual
// R_k = N(N_k) - N_k over the points either touches (0 where one does not),
//     N_{k+1} = N_k + w_k R_k,
//     w_k = -w_{k-1} R_{k-1} . (R_k - R_{k-1}) / |R_k - R_{k-1}|^2,
// w_0 = 1 (the plain iteration), w_k kept in [0.1, 5]. Where the plain
// iteration overshoots -- N and the friction pull each other back and
// forth, and a grasp's normal forces oscillate with a ratio near -1 -- w
// falls to about a half and the oscillation dies in a few solves; where it
// creeps (the load shifting slowly from one group of points to another,
// ratio 0.8 on the benchmark's cylinder) w grows beyond 1. On a linear map
// it is the secant method along the residual. A point whose relaxed force
// is not positive loses its anchor.
#include <softchain/chain/chain_load.h>

#include <map>
#include <utility>
#include <vector>

namespace softchain::chain
{
  class AitkenRelaxation
  {
  public:
    // The anchors of the next solve: positions and normals as `found` has
    // them (or `lagged` where a point no longer touches), normal forces
    // relaxed. One object per load step.
    std::vector<StickAnchor> next(const std::vector<StickAnchor> &lagged, const std::vector<StickAnchor> &found);
    double                   factor() const { return omega_; } // w of the last call

  private:
    double                                omega_ = 1.0;
    std::map<std::pair<int, int>, double> residual_; // R_{k-1} by (point, obstacle)
  };
} // namespace softchain::chain
