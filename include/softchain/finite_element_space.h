#pragma once
// FiniteElementSpace: the distributed mesh, the vector-valued Lagrange element
// (Q1/Q2 on hexahedra, P1/P2 on tetrahedra), its mapping and quadratures, the
// DoF partitioning and the Dirichlet constraints (clamped base, symmetry
// faces). Every physics operator (material, follower pressure, springs, point
// loads) works on one of these.
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <string>

namespace softchain
{
  using namespace dealii;

  class FiniteElementSpace
  {
  public:
    // `serial_mesh` is partitioned over `communicator` (METIS); `element_type`
    // is Q1, Q2, P1 or P2 and must match the mesh's cell shape.
    FiniteElementSpace(const Triangulation<3> &serial_mesh,
                       const std::string      &element_type,
                       MPI_Comm                communicator);

    MPI_Comm                                 communicator;
    parallel::fullydistributed::Triangulation<3> triangulation;
    std::unique_ptr<FESystem<3>>             fe;
    std::unique_ptr<Mapping<3>>              mapping;
    Quadrature<3>                            cell_quadrature;
    Quadrature<2>                            face_quadrature;
    DoFHandler<3>                            dof_handler;
    IndexSet                                 owned_dofs;
    IndexSet                                 relevant_dofs;
    // u = 0 on `base`; u_x, u_y, u_z = 0 on `fixed_x`, `fixed_y`, `fixed_z`.
    AffineConstraints<double>                fixed_dofs;
    bool                                     simplex;
    unsigned int                             degree;

    // Reference position of each DoF's support point for the DoFs of
    // locally owned cells (component c of node k).
    Point<3> support_point(const typename DoFHandler<3>::active_cell_iterator &cell,
                           unsigned int                                       base_index) const;

  private:
    void setup_dofs();
  };
} // namespace softchain
