#include <softchain/data/input_error.h>
#include <softchain/report/surface_mesh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <map>
#include <string>

namespace softchain::report
{
  namespace
  {
    using LocalFaces = std::vector<std::vector<int>>;

    // The faces of a reference cell, each in cyclic order around the face.
    // Hexahedron vertex v = i + 2 j + 4 k (x fastest, then y, then z).
    const LocalFaces &local_faces(const int nodes_per_cell)
    {
      static const LocalFaces tetrahedron = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      static const LocalFaces hexahedron  = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
      if (nodes_per_cell == 4)
        return tetrahedron;
      if (nodes_per_cell == 8)
        return hexahedron;
      throw data::InputError("/mesh/cells: " + std::to_string(nodes_per_cell) +
                             " nodes per cell, expected 4 (tetrahedra) or 8 (hexahedra)");
    }

    Eigen::Vector3d position(const data::MeshRecord &mesh, const std::int64_t node)
    {
      if (node < 0 || node >= static_cast<std::int64_t>(mesh.X.size()))
        throw data::InputError("/mesh/cells: node " + std::to_string(node) + " is not in /mesh/X (" +
                               std::to_string(mesh.X.size()) + " nodes)");
      const data::Point3 &p = mesh.X[node];
      return {p[0], p[1], p[2]};
    }

    // Newell's normal: exact for planar polygons, the average plane's normal
    // for a warped quadrilateral.
    Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d> &corners)
    {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < corners.size(); ++i)
        n += corners[i].cross(corners[(i + 1) % corners.size()]);
      return n;
    }

    Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d> &points)
    {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto &p : points)
        c += p;
      return c / points.size();
    }

    // Reverses `face` unless its normal points away from its cell's centroid.
    void orient_outward(SurfaceMesh::Face &face, const data::MeshRecord &mesh,
                        const Eigen::Vector3d &cell_centroid)
    {
      std::vector<Eigen::Vector3d> corners;
      for (const std::int64_t node : face)
        corners.push_back(position(mesh, node));
      if (newell_normal(corners).dot(centroid(corners) - cell_centroid) < 0)
        std::reverse(face.begin(), face.end());
    }
  } // namespace

  SurfaceMesh::SurfaceMesh(const data::MeshRecord &mesh)
  {
    const int         k       = mesh.nodes_per_cell;
    const LocalFaces &locals  = local_faces(k);
    const std::size_t n_cells = mesh.cells.size() / k;
    // Every face keyed by its sorted nodes: how many cells use it, and its
    // outward-oriented nodes as seen from the first one.
    std::map<Face, std::pair<int, Face>> seen;
    for (std::size_t c = 0; c < n_cells; ++c)
      {
        std::vector<Eigen::Vector3d> cell_corners;
        for (int v = 0; v < k; ++v)
          cell_corners.push_back(position(mesh, mesh.cells[c * k + v]));
        const Eigen::Vector3d cell_centroid = centroid(cell_corners);
        for (const auto &local : locals)
          {
            Face face;
            for (const int v : local)
              face.push_back(mesh.cells[c * k + v]);
            Face key = face;
            std::sort(key.begin(), key.end());
            auto &[count, oriented] = seen[key];
            if (count++ == 0)
              {
                orient_outward(face, mesh, cell_centroid);
                oriented = face;
              }
          }
      }
    for (const auto &[key, entry] : seen)
      if (entry.first == 1)
        faces_.push_back(entry.second);
  }
} // namespace softchain::report
