#include <softchain/fem/load_state.h>

namespace softchain::fem
{
  using namespace dealii;

  LoadState LoadState::interpolate(const LoadState &start, const LoadState &target, const double s)
  {
    LoadState state;
    state.pressure       = (1 - s) * start.pressure + s * target.pressure;
    state.gravity_factor = (1 - s) * start.gravity_factor + s * target.gravity_factor;
    state.tip_traction   = (1 - s) * start.tip_traction + s * target.tip_traction;
    state.obstacle_motion = (1 - s) * start.obstacle_motion + s * target.obstacle_motion;
    if (target.tip_motion)
      {
        const TipMotion from = start.tip_motion.value_or(TipMotion());
        state.tip_motion     = TipMotion{(1 - s) * from.translation + s * target.tip_motion->translation,
                                     (1 - s) * from.rotation + s * target.tip_motion->rotation,
                                     target.tip_motion->point_contact};
      }
    // Forces at the same point blend; a point present at one end only ramps
    // from or to zero.
    auto add = [&state](const PointLoad &load, const double factor) {
      for (auto &existing : state.point_loads)
        if (existing.point.distance(load.point) == 0.0)
          {
            existing.force += factor * load.force;
            return;
          }
      state.point_loads.push_back({load.point, factor * load.force});
    };
    for (const auto &l : start.point_loads)
      add(l, 1 - s);
    for (const auto &l : target.point_loads)
      add(l, s);
    return state;
  }
} // namespace softchain::fem
