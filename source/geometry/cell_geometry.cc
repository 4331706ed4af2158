#include <softchain/geometry/cell_geometry.h>

#include <Eigen/Geometry> // cross products

namespace softchain::geometry
{
  namespace
  {
    // gmsh hexahedron: nodes 0-3 the bottom quadrilateral, 4-7 the top one
    // above them. Six positively oriented tetrahedra around the diagonal 0-6.
    const std::array<CellGeometry::Tetrahedron, 6> hexahedron_split = {
      {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}}};

    const std::vector<std::vector<std::size_t>> tetrahedron_faces = {
      {0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const std::vector<std::vector<std::size_t>> hexahedron_faces = {
      {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  } // namespace

  std::vector<CellGeometry::Tetrahedron> CellGeometry::tetrahedra(const MshElement &cell)
  {
    const auto &n = cell.nodes;
    if (n.size() == 4)
      return {{n[0], n[1], n[2], n[3]}};
    std::vector<Tetrahedron> result;
    for (const auto &local : hexahedron_split)
      result.push_back({n[local[0]], n[local[1]], n[local[2]], n[local[3]]});
    return result;
  }

  double CellGeometry::signed_volume(const std::vector<Eigen::Vector3d> &nodes, const Tetrahedron &t)
  {
    const Eigen::Vector3d &x0 = nodes[t[0]];
    return (nodes[t[1]] - x0).dot((nodes[t[2]] - x0).cross(nodes[t[3]] - x0)) / 6.0;
  }

  double CellGeometry::volume(const MshFile &mesh, const MshElement &cell)
  {
    double v = 0.0;
    for (const auto &t : tetrahedra(cell))
      v += signed_volume(mesh.nodes, t);
    return v;
  }

  double CellGeometry::total_volume(const MshFile &mesh)
  {
    double v = 0.0;
    for (const auto &cell : mesh.cells)
      v += volume(mesh, cell);
    return v;
  }

  Eigen::Vector3d CellGeometry::centroid(const MshFile &mesh, const std::vector<std::size_t> &nodes)
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const std::size_t n : nodes)
      c += mesh.nodes[n];
    return c / static_cast<double>(nodes.size());
  }

  std::vector<std::vector<std::size_t>> CellGeometry::faces(const MshElement &cell)
  {
    const auto &local = cell.nodes.size() == 4 ? tetrahedron_faces : hexahedron_faces;
    std::vector<std::vector<std::size_t>> result;
    for (const auto &face : local)
      {
        std::vector<std::size_t> global;
        for (const std::size_t i : face)
          global.push_back(cell.nodes[i]);
        result.push_back(global);
      }
    return result;
  }
} // namespace softchain::geometry
