#include <softchain/geometry/reinforcement.h>

#include <algorithm>
#include <cmath>

namespace softchain::geometry
{
  namespace
  {
    // n + 1 evenly spaced values from a to b, n the fewest steps no longer than `spacing`.
    std::vector<double> even_steps(double a, double b, double spacing)
    {
      const int           n = std::max(1, static_cast<int>(std::ceil((b - a) / spacing)));
      std::vector<double> values;
      for (int i = 0; i <= n; ++i)
        values.push_back(a + (b - a) * i / n);
      return values;
    }

    // Points from a toward b (b excluded), no further apart than `spacing`.
    void append_side(std::vector<Eigen::Vector3d> &points, const Eigen::Vector3d &a,
                     const Eigen::Vector3d &b, double spacing)
    {
      const auto t = even_steps(0.0, 1.0, spacing / (b - a).norm());
      for (std::size_t i = 0; i + 1 < t.size(); ++i)
        points.push_back(a + t[i] * (b - a));
    }

    SpringNetwork::Polyline ring(const FingerDimensions &d, const SpringLayout &layout, double x)
    {
      // Through the middle of the bottom layer and of the side and top walls.
      const double z = 0.5 * (d.width(x) - d.wall);
      const double low = 0.5 * d.bottom, high = d.height(x) - 0.5 * d.wall;
      const std::vector<Eigen::Vector3d> corners{
        {x, low, -z}, {x, low, z}, {x, high, z}, {x, high, -z}};
      SpringNetwork::Polyline polyline{true, {}};
      for (std::size_t c = 0; c < corners.size(); ++c)
        append_side(polyline.points, corners[c], corners[(c + 1) % corners.size()],
                    layout.thread_node_spacing);
      return polyline;
    }
  } // namespace

  SpringNetwork Reinforcement::fabric(const FingerDimensions &d, const SpringLayout &layout)
  {
    // Half a wall thickness in from the base, tip and side faces.
    const double margin = 0.5 * d.wall;
    const auto   xs     = even_steps(margin, d.length - margin, layout.fabric_spacing);
    const double widest = std::max(d.base_width, d.tip_width) - d.wall;
    const auto   across = even_steps(-1.0, 1.0, 2.0 * layout.fabric_spacing / widest);
    const auto   node   = [&](double x, double s) {
      return Eigen::Vector3d(x, layout.fabric_height, s * 0.5 * (d.width(x) - d.wall));
    };
    SpringNetwork fabric{"fabric", {}};
    for (const double s : across)
      {
        fabric.polylines.push_back({false, {}});
        for (const double x : xs)
          fabric.polylines.back().points.push_back(node(x, s));
      }
    for (const double x : xs)
      {
        fabric.polylines.push_back({false, {}});
        for (const double s : across)
          fabric.polylines.back().points.push_back(node(x, s));
      }
    return fabric;
  }

  SpringNetwork Reinforcement::threads(const FingerDimensions &d, const SpringLayout &layout)
  {
    // Rings at cavity_start + (k + 1/2) pitch, k = 0, 1, ... before cavity_end.
    const int n_rings = static_cast<int>(
      std::ceil((d.cavity_end() - d.cavity_start()) / layout.thread_pitch - 0.5));
    SpringNetwork threads{"thread", {}};
    for (int k = 0; k < n_rings; ++k)
      threads.polylines.push_back(ring(d, layout, d.cavity_start() + (k + 0.5) * layout.thread_pitch));
    return threads;
  }
} // namespace softchain::geometry
