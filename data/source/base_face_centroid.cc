#include <softchain/data/base_face_centroid.h>
#include <softchain/data/input_error.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <vector>

namespace softchain::data
{
  namespace
  {
    // The corner nodes of each face of a cell, in cyclic order: tetrahedra,
    // and hexahedra in deal.II's lexicographic vertex order (x fastest).
    const std::vector<std::vector<int>> &faces_of(const int nodes_per_cell)
    {
      static const std::vector<std::vector<int>> tet = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      static const std::vector<std::vector<int>> hex = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                        {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
      return nodes_per_cell == 4 ? tet : hex;
    }
  } // namespace

  Eigen::Vector3d base_face_centroid(const MeshRecord &mesh)
  {
    const std::set<std::int64_t> base(mesh.base_nodes.begin(), mesh.base_nodes.end());
    const auto                   X = [&](std::int64_t i) { return vector_of(mesh.X[i]); };
    double          area = 0.0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    const int       k      = mesh.nodes_per_cell;
    for (std::size_t c = 0; c + k <= mesh.cells.size(); c += k)
      for (const auto &face : faces_of(k))
        {
          if (!std::all_of(face.begin(), face.end(),
                           [&](int v) { return base.count(mesh.cells[c + v]) > 0; }))
            continue;
          // A fan of triangles from the face's first corner.
          for (std::size_t v = 1; v + 1 < face.size(); ++v)
            {
              const Eigen::Vector3d a = X(mesh.cells[c + face[0]]), b = X(mesh.cells[c + face[v]]),
                                    d = X(mesh.cells[c + face[v + 1]]);
              const double triangle = 0.5 * (b - a).cross(d - a).norm();
              area += triangle;
              moment += triangle * (a + b + d) / 3.0;
            }
        }
    if (!(area > 0))
      throw InputError("the database mesh has no base face (/mesh/base_nodes and /mesh/cells)");
    return moment / area;
  }
} // namespace softchain::data
