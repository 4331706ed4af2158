#pragma once
// PointLocator: finds the cell of a mesh that contains a point (the
// barycentric test on each cell's tetrahedra), with a uniform bucket grid
// over the cells' bounding boxes so a query looks at a few cells only.
#include <softchain/geometry/cell_geometry.h>

#include <optional>

namespace softchain::geometry
{
  class PointLocator
  {
  public:
    // Keeps a reference: `mesh` must outlive the locator.
    explicit PointLocator(const MshFile &mesh);

    // Index into mesh.cells of a cell containing p, if any. A point on a
    // face shared by two cells is found in one of them.
    std::optional<std::size_t> locate(const Eigen::Vector3d &p) const;

  private:
    struct Entry
    {
      std::size_t               cell;
      CellGeometry::Tetrahedron tet;
    };
    void               insert(const Entry &entry);
    std::array<int, 3> bucket_of(const Eigen::Vector3d &p) const;
    std::size_t        flat(const std::array<int, 3> &b) const;
    bool               contains(const CellGeometry::Tetrahedron &t, const Eigen::Vector3d &p) const;

    const MshFile                  &mesh_;
    Eigen::Vector3d                 lower_, bucket_size_;
    std::array<int, 3>              n_buckets_{};
    std::vector<std::vector<Entry>> buckets_;
  };
} // namespace softchain::geometry
