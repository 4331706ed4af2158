#pragma once
// owned_boundary_dofs: the locally owned DoFs on the faces with one boundary
// id, each with its displacement component and its support point in the
// reference configuration -- what the base reaction (BaseReaction) sums and
// a prescribed tip motion (PrescribedTip) moves.
#include <softchain/fem/finite_element_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <vector>

namespace softchain::fem
{
  struct BoundaryDof
  {
    dealii::types::global_dof_index index;
    unsigned int                    component;
    dealii::Point<3>                support_point; // reference X
  };

  // Each rank lists the DoFs it owns (no communication).
  std::vector<BoundaryDof> owned_boundary_dofs(const FiniteElementSpace  &space,
                                               dealii::types::boundary_id boundary);
} // namespace softchain::fem
