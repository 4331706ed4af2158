#include <softchain/chain/aitken_relaxation.h>

#include <algorithm>

namespace softchain::chain
{
  std::vector<StickAnchor> AitkenRelaxation::next(const std::vector<StickAnchor> &lagged,
                                                  const std::vector<StickAnchor> &found)
  {
    std::map<std::pair<int, int>, std::pair<const StickAnchor *, const StickAnchor *>> points;
    for (const StickAnchor &a : lagged)
      points[{a.point, a.obstacle}].first = &a;
    for (const StickAnchor &a : found)
      points[{a.point, a.obstacle}].second = &a;
    std::map<std::pair<int, int>, double> residual;
    for (const auto &[key, pair] : points)
      residual[key] =
        (pair.second ? pair.second->normal_force : 0.0) - (pair.first ? pair.first->normal_force : 0.0);
    if (!residual_.empty())
      {
        std::map<std::pair<int, int>, double> change = residual;
        for (const auto &[key, r] : residual_)
          change[key] -= r;
        double along = 0.0, square = 0.0;
        for (const auto &[key, d] : change)
          {
            const auto previous = residual_.find(key);
            along += (previous != residual_.end() ? previous->second : 0.0) * d;
            square += d * d;
          }
        if (square > 0.0)
          omega_ = std::clamp(-omega_ * along / square, 0.1, 5.0);
      }
    residual_ = residual;
    std::vector<StickAnchor> next;
    for (const auto &[key, pair] : points)
      {
        StickAnchor anchor = pair.second ? *pair.second : *pair.first;
        anchor.normal_force = (pair.first ? pair.first->normal_force : 0.0) + omega_ * residual[key];
        if (anchor.normal_force > 0.0)
          next.push_back(anchor);
      }
    return next;
  }

} // namespace softchain::chain
