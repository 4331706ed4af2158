#include <softchain/chain/collision_surface.h>

#include <algorithm>
#include <stdexcept>

namespace softchain::chain
{
  CollisionSurface::CollisionSurface(std::vector<int> links, std::vector<Row> rows, const int n_links,
                                     std::vector<char> gives, std::vector<char> between_vertices)
    : links_(std::move(links))
    , rows_(std::move(rows))
    , gives_(gives.empty() ? std::vector<char>(links_.size(), 1) : std::move(gives))
    , between_vertices_(between_vertices.empty() ? std::vector<char>(links_.size(), 0) : std::move(between_vertices))
    , link_begin_(n_links + 1, 0)
  {
    if (gives_.size() != links_.size())
      throw std::invalid_argument("CollisionSurface: one 'gives' flag per point");
    if (between_vertices_.size() != links_.size())
      throw std::invalid_argument("CollisionSurface: one 'between vertices' flag per point");
    if (rows_.empty() || rows_.front().pressure != 0.0)
      throw std::invalid_argument("CollisionSurface: the first row must be the rest surface (p = 0)");
    for (std::size_t r = 0; r < rows_.size(); ++r)
      if (rows_[r].offsets.size() != links_.size() || (r > 0 && !(rows_[r].pressure > rows_[r - 1].pressure)))
        throw std::invalid_argument(
          "CollisionSurface: every row needs one offset per point, rows by increasing pressure");
    if (!std::is_sorted(links_.begin(), links_.end()) ||
        (!links_.empty() && (links_.front() < 0 || links_.back() >= n_links)))
      throw std::invalid_argument("CollisionSurface: points must be sorted by link, on links 0..n-1");
    for (int b = 0; b < n_links; ++b)
      link_begin_[b + 1] = static_cast<int>(std::upper_bound(links_.begin(), links_.end(), b) - links_.begin());
    for (int b = 0; b < n_links; ++b)
      if (link_begin_[b] < link_begin_[b + 1])
        split(b, link_begin_[b], link_begin_[b + 1]);
    for (std::size_t r = 0; r + 1 < std::max<std::size_t>(rows_.size(), 2); ++r)
      spheres_.push_back(spheres_between(rows_[r], rows_[std::min(r + 1, rows_.size() - 1)]));
  }

  // Halves [begin, end) at the median of the rest offsets along their
  // longest extent until a run has at most 8 points, a cluster. Nodes in
  // pre-order, each with the index past its subtree.
  int CollisionSurface::split(const int link, const int begin, const int end)
  {
    const std::vector<Eigen::Vector3d> &rest  = rows_.front().offsets;
    const int                           index = static_cast<int>(nodes_.size());
    nodes_.push_back({link, -1, begin, end, 0});
    if (end - begin > 8)
      {
        Eigen::Vector3d low = rest[begin], high = rest[begin];
        for (int k = begin; k < end; ++k)
          {
            low  = low.cwiseMin(rest[k]);
            high = high.cwiseMax(rest[k]);
          }
        Eigen::Index axis;
        (high - low).maxCoeff(&axis);
        std::vector<int> order(links_.size());
        for (std::size_t k = 0; k < order.size(); ++k)
          order[k] = static_cast<int>(k);
        std::stable_sort(order.begin() + begin, order.begin() + end,
                         [&](int a, int b) { return rest[a][axis] < rest[b][axis]; });
        reorder(order);
        const int middle = (begin + end) / 2;
        split(link, begin, middle);
        split(link, middle, end);
      }
    else
      {
        nodes_[index].cluster = static_cast<int>(clusters_.size());
        clusters_.push_back({link, begin, end});
      }
    nodes_[index].skip = static_cast<int>(nodes_.size());
    return index;
  }

  // Children before parents (reverse pre-order). A cluster's sphere: the
  // mean of its points at both rows as centre, the farthest of them as
  // radius; a node above: the mean likewise, the radius that holds both
  // children's spheres (so that it bounds everything they bound).
  std::vector<CollisionSurface::Sphere> CollisionSurface::spheres_between(const Row &r0, const Row &r1) const
  {
    std::vector<Sphere> spheres(nodes_.size());
    for (int n = static_cast<int>(nodes_.size()) - 1; n >= 0; --n)
      {
        const Node &node   = nodes_[n];
        Sphere     &sphere = spheres[n];
        for (int k = node.begin; k < node.end; ++k)
          sphere.centre += (r0.offsets[k] + r1.offsets[k]) / (2.0 * (node.end - node.begin));
        if (node.cluster >= 0)
          for (int k = node.begin; k < node.end; ++k)
            sphere.radius = std::max({sphere.radius, (r0.offsets[k] - sphere.centre).norm(),
                                      (r1.offsets[k] - sphere.centre).norm()});
        else
          for (const int child : {n + 1, nodes_[n + 1].skip})
            sphere.radius =
              std::max(sphere.radius, (spheres[child].centre - sphere.centre).norm() + spheres[child].radius);
      }
    return spheres;
  }

  // The interval [p_i, p_i+1] that holds p; below 0 the first (its start is
  // the rest row that offsets_at takes there), beyond the table the last.
  const std::vector<CollisionSurface::Sphere> &CollisionSurface::spheres_at(const double pressure) const
  {
    const auto above = std::upper_bound(rows_.begin(), rows_.end(), pressure,
                                        [](double p, const Row &row) { return p < row.pressure; });
    const auto row   = static_cast<std::size_t>(above - rows_.begin());
    return spheres_[std::min(row == 0 ? 0 : row - 1, spheres_.size() - 1)];
  }

  // Point k becomes point order[k]'s in every row.
  void CollisionSurface::reorder(const std::vector<int> &order)
  {
    for (Row &row : rows_)
      {
        std::vector<Eigen::Vector3d> moved(order.size());
        for (std::size_t k = 0; k < order.size(); ++k)
          moved[k] = row.offsets[order[k]];
        row.offsets = std::move(moved);
      }
    for (std::vector<char> *flags : {&gives_, &between_vertices_})
      {
        std::vector<char> moved(order.size());
        for (std::size_t k = 0; k < order.size(); ++k)
          moved[k] = (*flags)[order[k]];
        *flags = std::move(moved);
      }
  }

  std::vector<double> CollisionSurface::table_pressures() const
  {
    std::vector<double> pressures;
    for (const Row &row : rows_)
      pressures.push_back(row.pressure);
    return pressures;
  }

  // Linear between the two rows around p, the last row beyond it (negative
  // pressures take the rest row).
  void CollisionSurface::offsets_at(const double pressure, std::vector<Eigen::Vector3d> &offsets) const
  {
    offsets.resize(links_.size());
    const auto above = std::upper_bound(rows_.begin(), rows_.end(), pressure,
                                        [](double p, const Row &row) { return p < row.pressure; });
    if (above == rows_.begin() || above == rows_.end())
      {
        offsets = above == rows_.end() ? rows_.back().offsets : rows_.front().offsets;
        return;
      }
    const Row   &low = *(above - 1), &high = *above;
    const double t   = (pressure - low.pressure) / (high.pressure - low.pressure);
    for (std::size_t k = 0; k < links_.size(); ++k)
      offsets[k] = (1.0 - t) * low.offsets[k] + t * high.offsets[k];
  }
} // namespace softchain::chain
