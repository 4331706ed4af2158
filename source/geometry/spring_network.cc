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

  std::size_t SpringNetwork::n_springs() const
  {
    std::size_t n = 0;
    for (const auto &line : polylines)
      if (line.points.size() > 1)
        n += line.points.size() - (line.closed ? 0 : 1);
    return n;
  }
} // namespace softchain::geometry
