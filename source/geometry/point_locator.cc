#include <softchain/geometry/point_locator.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace softchain::geometry
{
  namespace
  {
    // Relative tolerance of the barycentric test: points on a face count as
    // inside (round-off of the coordinates, ~1e-16, is far below it).
    constexpr double barycentric_tolerance = 1e-10;

    std::pair<Eigen::Vector3d, Eigen::Vector3d> bounding_box(const std::vector<Eigen::Vector3d> &points)
    {
      Eigen::Vector3d lower = points.front(), upper = points.front();
      for (const auto &p : points)
        {
          lower = lower.cwiseMin(p);
          upper = upper.cwiseMax(p);
        }
      return {lower, upper};
    }
  } // namespace

  PointLocator::PointLocator(const MshFile &mesh)
    : mesh_(mesh)
  {
    const auto [lower, upper] = bounding_box(mesh.nodes);
    lower_                    = lower;
    // About one cell per bucket: n^3 buckets for n^3 cells, at most 64^3.
    const int n  = std::clamp(static_cast<int>(std::cbrt(double(mesh.cells.size()))), 1, 64);
    n_buckets_   = {n, n, n};
    bucket_size_ = ((upper - lower) / double(n)).cwiseMax(1e-300);
    buckets_.resize(std::size_t(n) * n * n);
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      for (const auto &tet : CellGeometry::tetrahedra(mesh.cells[c]))
        insert({c, tet});
  }

  void PointLocator::insert(const Entry &entry)
  {
    std::vector<Eigen::Vector3d> corners;
    for (const std::size_t node : entry.tet)
      corners.push_back(mesh_.nodes[node]);
    const auto [lower, upper] = bounding_box(corners);
    const auto a = bucket_of(lower), b = bucket_of(upper);
    for (int i = a[0]; i <= b[0]; ++i)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int k = a[2]; k <= b[2]; ++k)
          buckets_[flat({i, j, k})].push_back(entry);
  }

  std::array<int, 3> PointLocator::bucket_of(const Eigen::Vector3d &p) const
  {
    std::array<int, 3> b;
    for (int d = 0; d < 3; ++d)
      b[d] = std::clamp(static_cast<int>(std::floor((p[d] - lower_[d]) / bucket_size_[d])), 0,
                        n_buckets_[d] - 1);
    return b;
  }

  std::size_t PointLocator::flat(const std::array<int, 3> &b) const
  {
    return (std::size_t(b[0]) * n_buckets_[1] + b[1]) * n_buckets_[2] + b[2];
  }

  bool PointLocator::contains(const CellGeometry::Tetrahedron &t, const Eigen::Vector3d &p) const
  {
    const std::vector<Eigen::Vector3d> corners{mesh_.nodes[t[0]], mesh_.nodes[t[1]],
                                               mesh_.nodes[t[2]], mesh_.nodes[t[3]]};
    const double v = CellGeometry::signed_volume(corners, {0, 1, 2, 3});
    // Barycentric coordinate of each corner = volume with p in its place / v.
    for (std::size_t corner = 0; corner < 4; ++corner)
      {
        auto x   = corners;
        x[corner] = p;
        if (v * CellGeometry::signed_volume(x, {0, 1, 2, 3}) < -barycentric_tolerance * v * v)
          return false;
      }
    return true;
  }

  std::optional<std::size_t> PointLocator::locate(const Eigen::Vector3d &p) const
  {
    for (const auto &entry : buckets_[flat(bucket_of(p))])
      if (contains(entry.tet, p))
        return entry.cell;
    return std::nullopt;
  }
} // namespace softchain::geometry
