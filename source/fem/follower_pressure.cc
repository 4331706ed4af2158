#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/follower_pressure.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace softchain::fem
{
  using namespace dealii;

  FollowerPressure::FollowerPressure(const FiniteElementSpace &space)
    : space(space)
    , node_dofs(node_dof_table(*space.fe))
  {
    unsigned long local = 0;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          local += face->at_boundary() && face->boundary_id() == boundary::cavity;
    n_faces = Utilities::MPI::sum(local, space.communicator);
  }

  template <typename Function>
  void FollowerPressure::for_each_cavity_point(const TrilinosWrappers::MPI::Vector &u,
                                               Function                             f) const
  {
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                            update_values | update_gradients | update_normal_vectors |
                              update_JxW_values | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 3>>        grad_u(space.face_quadrature.size());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              cell->face(face)->boundary_id() == boundary::cavity)
            {
              fe_face.reinit(cell, face);
              fe_face[displacement].get_function_gradients(u, grad_u);
              for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
                {
                  const Tensor<2, 3> F = unit_symmetric_tensor<3>() + grad_u[q];
                  const Tensor<1, 3> cofF_N =
                    determinant(F) * transpose(invert(F)) * fe_face.normal_vector(q);
                  f(cell, fe_face, q, F, cofF_N);
                }
            }
  }

  void FollowerPressure::assemble(const TrilinosWrappers::MPI::Vector &u,
                                  const double                         p,
                                  const AffineConstraints<double>     &constraints,
                                  TrilinosWrappers::SparseMatrix      *matrix,
                                  TrilinosWrappers::MPI::Vector       &rhs,
                                  const CellMatrixScatter             *places) const
  {
    const unsigned int                   n = space.fe->n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Tensor<1, 3>>            g(node_dofs.size()); // F^-T Grad phi_b
    typename DoFHandler<3>::active_cell_iterator current;

    auto flush = [&]() {
      if (current.state() != IteratorState::valid)
        return;
      current->get_dof_indices(dofs);
      if (places)
        places->add(current->active_cell_index(), dofs, matrix ? &cell_matrix : nullptr, cell_rhs,
                    matrix, rhs);
      else if (matrix)
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, *matrix, rhs);
      else
        constraints.distribute_local_to_global(cell_rhs, dofs, rhs);
    };

    for_each_cavity_point(u, [&](const auto &cell, const FEFaceValues<3> &fe_face,
                                 const unsigned int q, const Tensor<2, 3> &F,
                                 const Tensor<1, 3> &cofF_N) {
      if (cell != current)
        {
          flush();
          current     = cell;
          cell_matrix = 0;
          cell_rhs    = 0;
        }
      if (matrix)
        {
          const Tensor<2, 3> F_invT = transpose(invert(F));
          for (unsigned int b = 0; b < node_dofs.size(); ++b)
            g[b] = F_invT * fe_face.shape_grad(node_dofs[b][0], q);
        }
      // cof(F) N = J n: the rows of node a are p phi_a dA0 times
      // -J n_c (load) and J (n_c g_b,d - g_b,c n_d) (stiffness).
      for (unsigned int a = 0; a < node_dofs.size(); ++a)
        {
          const double w = p * fe_face.shape_value(node_dofs[a][0], q) * fe_face.JxW(q);
          if (w == 0.0) // a node off this face
            continue;
          for (unsigned int c = 0; c < 3; ++c)
            cell_rhs(node_dofs[a][c]) -= w * cofF_N[c];
          if (matrix)
            for (unsigned int b = 0; b < node_dofs.size(); ++b)
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int d = 0; d < 3; ++d)
                  cell_matrix(node_dofs[a][c], node_dofs[b][d]) +=
                    w * (cofF_N[c] * g[b][d] - g[b][c] * cofF_N[d]);
        }
    });
    flush();
  }

  Tensor<1, 3> FollowerPressure::resultant(const TrilinosWrappers::MPI::Vector &u,
                                           const double                         p) const
  {
    Tensor<1, 3> force;
    for_each_cavity_point(u, [&](const auto &, const FEFaceValues<3> &fe_face,
                                 const unsigned int q, const Tensor<2, 3> &,
                                 const Tensor<1, 3> &cofF_N) {
      force -= p * cofF_N * fe_face.JxW(q);
    });
    return Utilities::MPI::sum(force, space.communicator);
  }

  double FollowerPressure::cavity_volume(const TrilinosWrappers::MPI::Vector &u) const
  {
    double                           volume = 0;
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 3>>        u_q(space.face_quadrature.size());
    for_each_cavity_point(u, [&](const auto &, const FEFaceValues<3> &fe_face,
                                 const unsigned int q, const Tensor<2, 3> &,
                                 const Tensor<1, 3> &cofF_N) {
      if (q == 0)
        fe_face[displacement].get_function_values(u, u_q);
      const Tensor<1, 3> x = fe_face.quadrature_point(q) + u_q[q];
      volume -= (x * cofF_N) * fe_face.JxW(q) / 3.0;
    });
    return Utilities::MPI::sum(volume, space.communicator);
  }
} // namespace softchain::fem
