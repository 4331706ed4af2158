#include <softchain/geometry/spring_network.h>

namespace softchain::geometry
{
  std::size_t SpringNetwork::n_nodes() const
  {
    std::size_t n = 0;
    for (const auto &line : polylines)
      n += line.points.size();
    return n;
  }
} // namespace softchain::geometry
