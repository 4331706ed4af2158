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
                                  TrilinosWrappers::MPI::Vector       &rhs) const
  {
    const unsigned int                   n = space.fe->n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    typename DoFHandler<3>::active_cell_iterator current;
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<1, 3>>            dcofF_N(n);

    auto flush = [&]() {
      if (current.state() != IteratorState::valid)
        return;
      current->get_dof_indices(dofs);
      if (matrix)
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
          current = cell;
          cell_matrix = 0;
          cell_rhs    = 0;
        }
      const double       JxW    = fe_face.JxW(q);
      const Tensor<2, 3> F_invT = transpose(invert(F));
      const Tensor<1, 3> FiTN   = F_invT * fe_face.normal_vector(q);
      const double       J      = determinant(F);
      if (matrix)
        for (unsigned int j = 0; j < n; ++j)
          {
            // d cof(F)[G] N = J ((F^-T : G) F^-T N - F^-T G^T F^-T N)
            const Tensor<2, 3> G = fe_face[displacement].gradient(j, q);
            dcofF_N[j] = J * (scalar_product(F_invT, G) * FiTN - F_invT * (transpose(G) * FiTN));
          }
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, 3> N_i = fe_face[displacement].value(i, q);
          cell_rhs(i) -= p * (N_i * cofF_N) * JxW;
          if (matrix)
            for (unsigned int j = 0; j < n; ++j)
              cell_matrix(i, j) += p * (N_i * dcofF_N[j]) * JxW;
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
