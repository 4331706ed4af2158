#include <softchain/geometry/finger_dimensions.h>

#include <algorithm>
#include <cmath>

namespace softchain::geometry
{
  namespace
  {
    // Integral over [a, b] of f(x) g(x) for f, g linear: Simpson's rule is
    // exact for the quadratic product.
    template <typename F, typename G>
    double integral_of_product(double a, double b, const F &f, const G &g)
    {
      const double m = 0.5 * (a + b);
      return (b - a) / 6.0 * (f(a) * g(a) + 4.0 * f(m) * g(m) + f(b) * g(b));
    }
  } // namespace

  double FingerDimensions::width(double x) const
  {
    return base_width + (tip_width - base_width) * x / length;
  }

  double FingerDimensions::height(double x) const
  {
    return base_height + (tip_height - base_height) * x / length;
  }

  double FingerDimensions::body_volume() const
  {
    return integral_of_product(
      0.0, length, [this](double x) { return width(x); }, [this](double x) { return height(x); });
  }

  double FingerDimensions::cavity_volume() const
  {
    return integral_of_product(
      cavity_start(), cavity_end(), [this](double x) { return width(x) - 2.0 * wall; },
      [this](double x) { return height(x) - wall - bottom; });
  }

  double FingerDimensions::material_volume() const
  {
    return body_volume() - cavity_volume();
  }

  double FingerDimensions::material_margin(const Eigen::Vector3d &p) const
  {
    const double x = p.x(), y = p.y(), z = std::abs(p.z());
    const double outer = std::min({x, length - x, y, height(x) - y, 0.5 * width(x) - z});
    // Gap to the cavity box along the axes; negative inside the cavity.
    const double cavity = std::max({cavity_start() - x, x - cavity_end(), bottom - y,
                                    y - (height(x) - wall), z - (0.5 * width(x) - wall)});
    return std::min(outer, cavity);
  }
} // namespace softchain::geometry
