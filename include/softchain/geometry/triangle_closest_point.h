#pragma once
// TriangleClosestPoint: the point of a triangle (a, b, c) closest to x and
// the feature it lies on -- a vertex, an edge or the face's inside.
// Ericson's region method (Real-Time Collision Detection, 2005, Sec. 5.1.5):
// with the dot products d1 = ab.ax, d2 = ac.ax, d3 = ab.bx, d4 = ac.bx,
// d5 = ab.cx, d6 = ac.cx, x lies in
//   vertex a's region where d1 <= 0 and d2 <= 0,
//   vertex b's where d3 >= 0 and d4 <= d3, vertex c's where d6 >= 0 and d5 <= d6,
//   edge ab's where v_c = d1 d4 - d3 d2 <= 0, d1 >= 0, d3 <= 0 (q = a + d1/(d1 - d3) ab),
//   edge ca's where v_b = d5 d2 - d1 d6 <= 0, d2 >= 0, d6 <= 0 (q = a + d2/(d2 - d6) ac),
//   edge bc's where v_a = d3 d6 - d5 d4 <= 0, d4 >= d3, d5 >= d6
//     (q = b + (d4 - d3)/((d4 - d3) + (d5 - d6)) bc),
//   else the face's, at barycentric weights (v_a, v_b, v_c) / (v_a + v_b + v_c).
// Edge e runs from vertex e to vertex (e + 1) % 3: 0 = ab, 1 = bc, 2 = ca.
#include <Eigen/Core>

namespace softchain::geometry
{
  struct TriangleClosestPoint
  {
    enum class Feature
    {
      vertex,
      edge,
      face
    };

    Eigen::Vector3d point;
    Feature         feature;
    int             index; // the vertex or the edge (0, 1, 2); 0 for the face
  };

  TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d &x, const Eigen::Vector3d &a,
                                                 const Eigen::Vector3d &b, const Eigen::Vector3d &c);
} // namespace softchain::geometry
