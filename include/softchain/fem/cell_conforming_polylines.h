#pragma once
// Splits spring polylines where they cross cell faces, so that every link
// lies in one cell. An embedded link then couples the DoFs of that cell only
// (instead of the union of two cells' DoFs), which keeps the tangent's
// sparsity pattern that of the solid: on the demo finger (Q2) the springs
// otherwise triple the cost of a sparse LU (docs/toolchain.md, "Linear solvers").
// Physically the split point is one more material point of the embedded
// fibre, so the fibre follows the body more closely.
#include <softchain/fem/spring_polyline.h>

#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace softchain::fem
{
  // The polylines' own nodes are kept (they set the fibre's resolution). A
  // crossing closer than `min_fraction` of the local cell size to a polyline
  // node is not inserted: that node is then evaluated slightly outside its
  // link's cell (EmbeddedPoints allows it), which avoids very short, very
  // stiff links.
  std::vector<SpringPolyline> cell_conforming_polylines(const std::vector<SpringPolyline> &polylines,
                                                        const dealii::Triangulation<3> &mesh,
                                                        const dealii::Mapping<3>       &mapping,
                                                        double                  min_fraction = 0.05);
} // namespace softchain::fem
