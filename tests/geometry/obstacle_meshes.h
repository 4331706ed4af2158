#pragma once
// Closed, outward-oriented triangle surfaces of known solids for the tests of
// TriangulatedObstacle (geometry) and of contact with it (FEM).
#include <softchain/geometry/stl_file.h>

#include <Eigen/Dense>

namespace softchain::geometry::testing
{
  // A box, two triangles per face, each face's corners counterclockwise
  // about its outward normal.
  inline StlFile box_surface(const Eigen::Vector3d &center, const Eigen::Vector3d &half_sizes,
                             const Eigen::Matrix3d &rotation = Eigen::Matrix3d::Identity())
  {
    StlFile stl;
    for (int a = 0; a < 3; ++a)
      for (const double side : {-1.0, 1.0})
        {
          const int                     u = (a + 1) % 3, v = (a + 2) % 3;
          std::array<Eigen::Vector3d, 4> q;
          int                           k = 0;
          for (const auto &[su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
            {
              Eigen::Vector3d y = Eigen::Vector3d::Zero();
              y[a]              = side * half_sizes[a];
              y[u]              = su * half_sizes[u];
              y[v]              = sv * half_sizes[v];
              q[k++]            = center + rotation * y;
            }
          // (u, v) counterclockwise is about +e_a: reversed on the - side.
          if (side < 0)
            std::swap(q[1], q[3]);
          stl.triangles.push_back({{q[0], q[1], q[2]}});
          stl.triangles.push_back({{q[0], q[2], q[3]}});
        }
    return stl;
  }

  // A sphere: the octahedron's faces split `levels` times into four, the
  // vertices pushed out onto the sphere (8 4^levels triangles).
  inline StlFile sphere_surface(const Eigen::Vector3d &center, const double radius, const int levels)
  {
    StlFile octahedron;
    for (const double sx : {-1.0, 1.0})
      for (const double sy : {-1.0, 1.0})
        for (const double sz : {-1.0, 1.0})
          {
            StlFile::Triangle t{{Eigen::Vector3d(sx, 0, 0), Eigen::Vector3d(0, sy, 0), Eigen::Vector3d(0, 0, sz)}};
            if (sx * sy * sz < 0)
              std::swap(t[1], t[2]);
            octahedron.triangles.push_back(t);
          }
    StlFile sphere = octahedron.subdivided(levels);
    for (auto &t : sphere.triangles)
      for (auto &v : t)
        v = center + radius * v.normalized();
    return sphere;
  }
} // namespace softchain::geometry::testing
