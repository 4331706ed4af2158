#include <softchain/geometry/triangle_closest_point.h>

namespace softchain::geometry
{
  TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d &x, const Eigen::Vector3d &a,
                                                 const Eigen::Vector3d &b, const Eigen::Vector3d &c)
  {
    using Feature            = TriangleClosestPoint::Feature;
    const Eigen::Vector3d ab = b - a, ac = c - a;
    const double          d1 = ab.dot(x - a), d2 = ac.dot(x - a);
    if (d1 <= 0 && d2 <= 0)
      return {a, Feature::vertex, 0};
    const double d3 = ab.dot(x - b), d4 = ac.dot(x - b);
    if (d3 >= 0 && d4 <= d3)
      return {b, Feature::vertex, 1};
    const double d5 = ab.dot(x - c), d6 = ac.dot(x - c);
    if (d6 >= 0 && d5 <= d6)
      return {c, Feature::vertex, 2};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
      return {a + d1 / (d1 - d3) * ab, Feature::edge, 0};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
      return {a + d2 / (d2 - d6) * ac, Feature::edge, 2};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
      return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), Feature::edge, 1};
    const double sum = va + vb + vc;
    return {a + (vb / sum) * ab + (vc / sum) * ac, Feature::face, 0};
  }
} // namespace softchain::geometry
