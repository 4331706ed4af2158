#include <softchain/geometry/triangle_tree.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace softchain::geometry
{
  namespace
  {
    constexpr int leaf_size = 4;
  } // namespace

  TriangleTree::TriangleTree(const std::vector<Eigen::Vector3d> &vertices,
                             const std::vector<std::array<int, 3>> &triangles)
    : vertices(vertices)
    , triangles(triangles)
    , order(triangles.size())
  {
    std::iota(order.begin(), order.end(), 0);
    for (const auto &t : triangles)
      centroids.push_back((vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) / 3);
    nodes.reserve(2 * triangles.size() / leaf_size + 2);
    build(0, static_cast<int>(triangles.size()));
  }

  int TriangleTree::build(const int first, const int count)
  {
    const int index = static_cast<int>(nodes.size());
    nodes.emplace_back();
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d high = -low, centre_low = low, centre_high = -low;
    for (int i = first; i < first + count; ++i)
      {
        for (const int v : triangles[order[i]])
          {
            low  = low.cwiseMin(vertices[v]);
            high = high.cwiseMax(vertices[v]);
          }
        centre_low  = centre_low.cwiseMin(centroids[order[i]]);
        centre_high = centre_high.cwiseMax(centroids[order[i]]);
      }
    nodes[index].low  = low;
    nodes[index].high = high;
    if (count <= leaf_size)
      {
        nodes[index].first = first;
        nodes[index].count = count;
        return index;
      }
    int axis = 0;
    (centre_high - centre_low).maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                     [&](const int a, const int b) { return centroids[a][axis] < centroids[b][axis]; });
    const int left     = build(first, half);
    const int right    = build(first + half, count - half);
    nodes[index].left  = left;
    nodes[index].right = right;
    return index;
  }

  double TriangleTree::squared_distance_to_box(const Node &node, const Eigen::Vector3d &x) const
  {
    return ((node.low - x).cwiseMax(0.0) + (x - node.high).cwiseMax(0.0)).squaredNorm();
  }

  TriangleTree::Nearest TriangleTree::nearest(const Eigen::Vector3d &x) const
  {
    Nearest best{0, {x, TriangleClosestPoint::Feature::face, 0}, std::numeric_limits<double>::infinity()};
    std::vector<int> stack{0};
    stack.reserve(64);
    while (!stack.empty())
      {
        const Node &node = nodes[stack.back()];
        stack.pop_back();
        if (squared_distance_to_box(node, x) >= best.squared_distance)
          continue;
        if (node.left < 0)
          {
            for (int i = node.first; i < node.first + node.count; ++i)
              {
                const auto &t = triangles[order[i]];
                const auto  c = closest_point_on_triangle(x, vertices[t[0]], vertices[t[1]], vertices[t[2]]);
                const double d = (x - c.point).squaredNorm();
                if (d < best.squared_distance)
                  best = {static_cast<std::size_t>(order[i]), c, d};
              }
            continue;
          }
        const double left = squared_distance_to_box(nodes[node.left], x),
                     right = squared_distance_to_box(nodes[node.right], x);
        // The nearer child on top, searched first.
        if (left < right)
          stack.insert(stack.end(), {node.right, node.left});
        else
          stack.insert(stack.end(), {node.left, node.right});
      }
    return best;
  }
} // namespace softchain::geometry
