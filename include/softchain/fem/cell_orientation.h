#pragma once
// Inverted cells: the map from a cell's reference cell to its physical shape
// must have a positive Jacobian determinant everywhere, or the deformation
// gradient F (and J = det F) is measured against a folded reference and no
// solve can be trusted. Checked once per mesh, before any solve.
#include <deal.II/grid/tria.h>

#include <string>

namespace softchain::fem
{
  // The smallest scaled Jacobian of the mesh's cells: det[e1 e2 e3] /
  // (|e1| |e2| |e3|) of the three edges at each corner of a hexahedron
  // (trilinear map: its determinant's extremes over the cell include the
  // corners for mildly distorted cells, the usual corner test of mesh-quality
  // codes) and at vertex 0 of a tetrahedron (affine map: constant). 1 for a
  // box, about 0.7 for a regular tetrahedron, <= 0 for an inverted cell.
  double smallest_scaled_jacobian(const dealii::Triangulation<3> &mesh);

  // Throws data::InputError starting with `source` and naming the first
  // inverted cell (index, centre, scaled Jacobian).
  void check_cell_orientation(const dealii::Triangulation<3> &mesh, const std::string &source);
} // namespace softchain::fem
