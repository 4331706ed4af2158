#include <softchain/data/richardson_extrapolation.h>

#include <cmath>

namespace softchain::data
{
  RichardsonExtrapolation RichardsonExtrapolation::of(const std::array<double, 3> &h,
                                                      const std::array<double, 3> &f)
  {
    const double e21 = f[1] - f[0], e32 = f[2] - f[1];
    const RichardsonExtrapolation finest{f[0], std::abs(e21), 0.0, false};
    if (e21 == 0 && e32 == 0)
      return {f[0], 0.0, 0.0, true};
    if (e21 == 0 || e32 == 0 || e32 / e21 < 0)
      return finest;
    const double r21 = h[1] / h[0], r32 = h[2] / h[1];
    double       p   = 2;
    for (int k = 0; k < 200; ++k)
      {
        const double next =
          std::abs(std::log(std::abs(e32 / e21)) + std::log((std::pow(r21, p) - 1) / (std::pow(r32, p) - 1))) /
          std::log(r21);
        if (std::abs(next - p) < 1e-12)
          {
            p = next;
            break;
          }
        p = next;
      }
    if (!(p >= 0.5 && p <= 8))
      return finest;
    const double value = (std::pow(r21, p) * f[0] - f[1]) / (std::pow(r21, p) - 1);
    return {value, 1.25 * std::abs(f[0] - value), p, true};
  }
} // namespace softchain::data
