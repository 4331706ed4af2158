#pragma once
// FiniteElementSpace: the distributed mesh, the vector-valued Lagrange element
// (Q1/Q2 on hexahedra, P1/P2 on tetrahedra), its mapping and quadratures, the
// DoF partitioning and the Dirichlet constraints (clamped base, symmetry
// faces). Every physics operator (material, follower pressure, springs, point
// loads) works on one of these.
#include <softchain/fem/element_type.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <memory>
#include <vector>

namespace softchain::fem
{
  class FiniteElementSpace
  {
  public:
    // `serial_mesh` is partitioned over `communicator` (METIS); `element_type`
    // must match the mesh's cell shape.
    FiniteElementSpace(const dealii::Triangulation<3> &serial_mesh,
                       ElementType             element_type,
                       MPI_Comm                communicator);

    MPI_Comm                                 communicator;
    dealii::parallel::fullydistributed::Triangulation<3> triangulation;
    std::unique_ptr<dealii::FESystem<3>>             fe;
    std::unique_ptr<dealii::Mapping<3>>              mapping;
    dealii::Quadrature<3>                            cell_quadrature;
    dealii::Quadrature<2>                            face_quadrature;
    dealii::DoFHandler<3>                            dof_handler;
    dealii::IndexSet                                 owned_dofs;
    dealii::IndexSet                                 relevant_dofs;
    // u = 0 on `base`; u_x, u_y, u_z = 0 on `fixed_x`, `fixed_y`, `fixed_z`.
    dealii::AffineConstraints<double>                fixed_dofs;
    bool                                     simplex;
    unsigned int                             degree;

    // Reference position of each DoF's support point for the DoFs of
    // locally owned cells (component c of node k).
    dealii::Point<3> support_point(const typename dealii::DoFHandler<3>::active_cell_iterator &cell,
                           unsigned int                                       base_index) const;

  private:
    void setup_dofs();
  };

  // The vector elements here are three copies of one scalar element, so each
  // cell shape function is e_c phi_a: one scalar function phi_a (node a) times
  // one unit vector e_c. Returns table[a][c], the cell DoF of e_c phi_a; throws
  // if `fe` is not of that kind. The node-by-node kernels (HyperelasticCell,
  // FollowerPressure) work on it.
  std::vector<std::array<unsigned int, 3>> node_dof_table(const dealii::FiniteElement<3> &fe);
} // namespace softchain::fem
