#pragma once
// CellGeometry: the geometry of one mesh cell (tetrahedron or hexahedron in
// gmsh's node order). A hexahedron is split into six tetrahedra around its
// 0-6 diagonal; for planar faces (all SoftChain designs) the split is exact.
#include <softchain/geometry/msh_file.h>

#include <array>
#include <vector>

namespace softchain::geometry
{
  class CellGeometry
  {
  public:
    using Tetrahedron = std::array<std::size_t, 4>;

    static std::vector<Tetrahedron> tetrahedra(const MshElement &cell);
    // (x1-x0).((x2-x0)x(x3-x0)) / 6: positive for gmsh's orientation.
    static double signed_volume(const std::vector<Eigen::Vector3d> &nodes, const Tetrahedron &t);
    static double volume(const MshFile &mesh, const MshElement &cell);
    static double total_volume(const MshFile &mesh);
    static Eigen::Vector3d centroid(const MshFile &mesh, const std::vector<std::size_t> &nodes);
    // The faces of a cell (3 or 4 nodes each).
    static std::vector<std::vector<std::size_t>> faces(const MshElement &cell);
  };
} // namespace softchain::geometry
