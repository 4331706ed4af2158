#pragma once
// TriangulatedObstacle: the solid a closed triangle mesh bounds (Shape = stl).
// Its signed distance at x: the closest point q of the surface, over the
// triangles (closest_point_on_triangle, found through a TriangleTree), and
//     g = s |x - q|,   n = s (x - q) / |x - q|,
// with the sign s = sign((x - q) . m) of the angle-weighted pseudo-normal m
// of the feature q lies on (Baerentzen and Aanaes, "Signed distance
// computation using the angle weighted pseudonormal", IEEE TVCG 11, 2005):
// a face's normal; at an edge the sum of its two faces' normals; at a
// vertex the sum of its faces' normals, each weighted by the face's angle
// there. Where |x - q| is ~0 (on the surface) n is m / |m|.
// The Hessian is the curvature of the level set through x:
//     face:   H = 0,
//     edge:   H = (I - e e^T - n n^T) / g   (a cylinder about the edge, e its direction),
//     vertex: H = (I - n n^T) / g           (a sphere about the vertex),
// the box's (BoxObstacle) at its edges and corners; zero also at an edge
// or vertex where the faces meeting are coplanar (there the distance is a
// plane's).
//
// The mesh must be closed and consistently oriented: its vertices are
// merged where their coordinates are equal, and each edge must belong to
// exactly two triangles that run it in opposite directions. A mesh that
// encloses a negative volume (its triangles wound inward) is turned
// outward; volume = sum over the triangles of a . (b x c) / 6.
#include <softchain/geometry/rigid_obstacle.h>
#include <softchain/geometry/triangle_tree.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace softchain::geometry
{
  class TriangulatedObstacle : public RigidObstacle
  {
  public:
    using Triangle = std::array<Eigen::Vector3d, 3>;

    // `source` names the mesh (its file) in messages. Throws InputError
    // naming it for an empty, open or inconsistently oriented mesh or a
    // degenerate triangle.
    TriangulatedObstacle(const std::vector<Triangle> &triangles, const std::string &source);
    SignedDistance distance_at_rest(const Eigen::Vector3d &x) const override;
    std::string    shape() const override { return "stl"; }

    double volume() const { return enclosed_volume; }

  private:
    void merge_vertices(const std::vector<Triangle> &triangles);
    void check_edges() const;
    void orient_outward();
    void compute_pseudo_normals();

    std::string                       source;
    std::vector<Eigen::Vector3d>      vertices;
    std::vector<std::array<int, 3>>   faces;
    std::vector<Eigen::Vector3d>      face_normals;   // unit
    std::vector<std::array<Eigen::Vector3d, 3>> edge_normals; // per face and edge (vertex e to e + 1)
    std::vector<std::array<bool, 3>>  edge_flat;      // its two faces coplanar
    std::vector<Eigen::Vector3d>      vertex_normals;
    std::vector<bool>                 vertex_flat;    // all its faces coplanar
    double                            enclosed_volume = 0;
    double                            on_surface      = 0; // |x - q| below it: x on the surface
    std::unique_ptr<TriangleTree>     tree;
  };
} // namespace softchain::geometry
