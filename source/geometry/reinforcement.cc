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

    // Corner c (0: bottom -z, 1: bottom +z, 2: top +z, 3: top -z) of the
    // thread ring at x: through the middle of the bottom layer and of the
    // side and top walls.
    Eigen::Vector3d ring_corner(const FingerDimensions &d, double x, int c)
    {
      const double z = 0.5 * (d.width(x) - d.wall);
      const double y = c < 2 ? 0.5 * d.bottom : d.height(x) - 0.5 * d.wall;
      return {x, y, (c == 0 || c == 3) ? -z : z};
    }

    SpringNetwork::Polyline ring(const FingerDimensions &d, const SpringLayout &layout, double x)
    {
      SpringNetwork::Polyline polyline{true, {}};
      for (int c = 0; c < 4; ++c)
        append_side(polyline.points, ring_corner(d, x, c), ring_corner(d, x, (c + 1) % 4),
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
    SpringNetwork fabric{"fabric", {}, {}};
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
    SpringNetwork threads{"thread", {}, {}};
    for (int k = 0; k < n_rings; ++k)
      threads.polylines.push_back(ring(d, layout, d.cavity_start() + (k + 0.5) * layout.thread_pitch));
    return threads;
  }

  SpringNetwork Reinforcement::fabric_sheet(const FingerDimensions &d, const SpringLayout &layout)
  {
    const double x0 = 0.5 * d.wall, x1 = d.length - 0.5 * d.wall;
    const auto   half = [&](double x) { return 0.5 * (d.width(x) - d.wall); };
    const double y    = layout.fabric_height;
    FibreSheet   sheet{{{x0, y, -half(x0)}, {x1, y, -half(x1)}, {x1, y, half(x1)}, {x0, y, half(x0)}},
                     {{Eigen::Vector3d::UnitX(), layout.fabric_spacing},
                        {Eigen::Vector3d::UnitZ(), layout.fabric_spacing}}};
    return {"fabric", {}, {sheet}};
  }

  SpringNetwork Reinforcement::thread_sheets(const FingerDimensions &d, const SpringLayout &layout)
  {
    const double  x0 = d.cavity_start(), x1 = d.cavity_end();
    SpringNetwork threads{"thread", {}, {}};
    // Side c of the ring (from corner c to c + 1) swept from x0 to x1; its
    // hoop direction is that side's. Rings a pitch apart along x lie
    // pitch |t| / t_x apart in a strip that slopes with the taper (t: the
    // strip's direction across the hoops), so the sheet holds the rings'
    // thread length per unit length of finger.
    for (int c = 0; c < 4; ++c)
      {
        const Eigen::Vector3d a = ring_corner(d, x0, c), b = ring_corner(d, x0, (c + 1) % 4);
        const Eigen::Vector3d hoop = (b - a).normalized();
        const Eigen::Vector3d edge = ring_corner(d, x1, c) - a;
        const Eigen::Vector3d t    = edge - edge.dot(hoop) * hoop;
        threads.sheets.push_back({{a, ring_corner(d, x1, c), ring_corner(d, x1, (c + 1) % 4), b},
                                  {{hoop, layout.thread_pitch * t.norm() / t.x()}}});
      }
    return threads;
  }
} // namespace softchain::geometry
