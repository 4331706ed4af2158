#pragma once
// Quadrature of a planar sheet (a convex polygon in reference coordinates)
// over the cells it crosses: the polygon is clipped to each locally owned
// cell by the planes of the cell's faces (Sutherland-Hodgman), the clipped
// polygon fanned into triangles and each triangle integrated by a Gauss rule
// exact for degree 5. The rule thus follows the mesh: the sheet's integrand
// (the fibre strains, from the cell's displacement gradient) is smooth inside
// a cell and jumps across its faces, and no quadrature point straddles one.
//
// The cells must have planar faces: affine tetrahedra, and hexahedra whose
// faces are planar, like the parametric designs' (meshes/finger.geo). A sheet
// that lies in a face shared by two cells is counted once, in the cell its
// normal (corners 0, 1, 2, right-handed) points into.
#include <softchain/fem/finite_element_space.h>

#include <deal.II/base/point.h>

#include <vector>

namespace softchain::fem
{
  struct CellSheetQuadrature
  {
    dealii::DoFHandler<3>::active_cell_iterator cell;
    std::vector<dealii::Point<3>>               unit_points; // in the cell's reference cell
    std::vector<double>                         weights;     // area, m^2
  };

  std::vector<CellSheetQuadrature> sheet_quadrature(const FiniteElementSpace            &space,
                                                    const std::vector<dealii::Point<3>> &corners);
} // namespace softchain::fem
