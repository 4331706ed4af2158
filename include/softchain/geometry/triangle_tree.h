#pragma once
// TriangleTree: a bounding-volume hierarchy of axis-aligned boxes over a
// triangle mesh, for the triangle nearest a point. Built top-down: each node
// splits its triangles at the median of their centroids along the longest
// side of the centroids' box, down to leaves of at most four triangles.
// A query descends into the nearer child first and skips any node whose box
// lies farther than the nearest triangle found so far (the squared distance
// to a box is the sum over the axes of the squared excess of x beyond it),
// so it tests O(log n) triangles where the surface near x is not much
// denser than elsewhere.
#include <softchain/geometry/triangle_closest_point.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace softchain::geometry
{
  class TriangleTree
  {
  public:
    struct Nearest
    {
      std::size_t          triangle; // its index in the mesh
      TriangleClosestPoint closest;
      double               squared_distance;
    };

    TriangleTree(const std::vector<Eigen::Vector3d> &vertices, const std::vector<std::array<int, 3>> &triangles);
    // The triangle closest to x (the mesh must not be empty).
    Nearest nearest(const Eigen::Vector3d &x) const;

  private:
    struct Node
    {
      Eigen::Vector3d low, high;             // the box around its triangles
      int             first = 0, count = 0;  // a leaf's range in `order`
      int             left = -1, right = -1; // an inner node's children
    };

    int    build(int first, int count);
    double squared_distance_to_box(const Node &node, const Eigen::Vector3d &x) const;

    std::vector<Eigen::Vector3d>     vertices;
    std::vector<std::array<int, 3>> triangles;
    std::vector<int>                 order; // triangle indices, each leaf's contiguous
    std::vector<Eigen::Vector3d>     centroids;
    std::vector<Node>                nodes;
  };
} // namespace softchain::geometry
