#pragma once
// CavitySurface: the facets of the physical group "cavity" as triangles
// (quadrilaterals split in two), each oriented so that (x1-x0)x(x2-x0)
// points out of the body material, i.e. into the cavity (the convention of
// the database's /mesh/cavity_triangles). The orientation comes from the
// cell that owns the facet, not from the mesher.
#include <softchain/geometry/msh_file.h>

#include <array>
#include <vector>

namespace softchain::geometry
{
  class CavitySurface
  {
  public:
    // Throws InputError naming the file if the group is missing or a facet
    // is not the face of any cell.
    explicit CavitySurface(const MshFile &mesh);

    const std::vector<std::array<std::size_t, 3>> &triangles() const { return triangles_; }

    // Sum of the oriented area vectors: zero for a closed surface.
    Eigen::Vector3d area_vector_sum() const;
    double          total_area() const;
    // Volume enclosed by the cavity (divergence theorem), positive.
    double enclosed_volume() const;

  private:
    Eigen::Vector3d area_vector(const std::array<std::size_t, 3> &t) const;

    std::vector<Eigen::Vector3d>            nodes_; // copy of the mesh nodes
    std::vector<std::array<std::size_t, 3>> triangles_;
  };
} // namespace softchain::geometry
