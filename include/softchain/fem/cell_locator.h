#pragma once
// CellLocator: the active cell that holds a point, with the point's unit
// coordinates in it. Candidates come from an R-tree of cell bounding boxes;
// each is tested exactly: barycentric coordinates from the vertices for
// (affine) tetrahedra, the mapping's inversion for hexahedra. (deal.II 9.4's
// GridTools::find_active_cell_around_point accepts tetrahedra whose unit
// *cube* holds the point, i.e. up to ~20 % outside the tetrahedron, which
// would extrapolate the shape functions.)
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/grid/tria.h>

#include <optional>
#include <utility>

namespace softchain::fem
{
  class CellLocator
  {
  public:
    using Cell = dealii::Triangulation<3>::active_cell_iterator;

    CellLocator(const dealii::Triangulation<3> &mesh, const dealii::Mapping<3> &mapping);

    // Unit coordinates of p in `cell` if p lies in it up to `tolerance` (in
    // unit coordinates).
    std::optional<dealii::Point<3>> unit_point(const Cell &cell, const dealii::Point<3> &p,
                                       double tolerance = 1e-10) const;

    // The cell around p (the one p lies deepest in, if p is on a face) and
    // p's unit coordinates there; an invalid cell if p lies outside the mesh
    // by more than `tolerance`.
    std::pair<Cell, dealii::Point<3>> locate(const dealii::Point<3> &p, double tolerance = 1e-10) const;

  private:
    const dealii::Mapping<3>    &mapping;
    dealii::GridTools::Cache<3>  cache;
  };
} // namespace softchain::fem
