#include <softchain/chain/link_shift_per_turn.h>

#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  LinkShiftPerTurn::LinkShiftPerTurn(std::vector<ShiftInPressure> links)
    : links_(std::move(links))
  {
    if (links_.empty())
      throw std::invalid_argument("LinkShiftPerTurn: no links");
    for (const ShiftInPressure &link : links_)
      for (const PiecewiseLinear &table : link)
        for (const double g : table.values())
          if (!std::isfinite(g))
            throw std::invalid_argument("LinkShiftPerTurn: a shift per turn is not finite");
  }

  Eigen::Vector3d LinkShiftPerTurn::at(const double pressure, const int link) const
  {
    const ShiftInPressure &g = links_.at(link);
    return {g[0](pressure), g[1](pressure), 0.0};
  }

  std::vector<double> LinkShiftPerTurn::table_pressures() const
  {
    std::vector<double> pressures;
    for (const ShiftInPressure &link : links_)
      merge_abscissae({link[0], link[1]}, pressures);
    return pressures;
  }
} // namespace softchain::chain
