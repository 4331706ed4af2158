#pragma once
// SurfaceMesh: the boundary of a volume mesh as polygons, for drawing. A face
// of a cell is on the boundary when no other cell shares it (the outer skin
// and the cavity walls). The database stores each cell by its corner nodes
// only (ActuationDatabase: 4 for tetrahedra, 8 for hexahedra in deal.II's
// lexicographic order), also for quadratic elements, so a boundary face is a
// triangle or a quadrilateral of corner nodes: a quadratic face drawn flat.
#include <softchain/data/actuation_database.h>

#include <cstdint>
#include <vector>

namespace softchain::report
{
  class SurfaceMesh
  {
  public:
    // 3 or 4 node indices in cyclic order, oriented so that the normal
    // (x1 - x0) x (x2 - x0) points out of the face's cell in the reference
    // configuration (and so in every deformed one without inverted cells).
    using Face = std::vector<std::int64_t>;

    // Throws data::InputError for cells that are neither 4 nor 8 nodes or
    // name a node that /mesh/X does not hold.
    explicit SurfaceMesh(const data::MeshRecord &mesh);

    const std::vector<Face> &faces() const { return faces_; }

  private:
    std::vector<Face> faces_;
  };
} // namespace softchain::report
