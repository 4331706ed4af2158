#include <softchain/fem/dead_surface_traction.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    template <typename Function>
    void for_each_face(const FiniteElementSpace &space, const types::boundary_id boundary,
                       FEFaceValues<3> &fe_face, Function f)
    {
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto face : cell->face_indices())
            if (cell->face(face)->at_boundary() && cell->face(face)->boundary_id() == boundary)
              {
                fe_face.reinit(cell, face);
                f(cell);
              }
    }
  } // namespace

  DeadSurfaceTraction::DeadSurfaceTraction(const FiniteElementSpace &space,
                                           const types::boundary_id  boundary)
    : space(space)
    , boundary(boundary)
  {
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature, update_JxW_values);
    double          local = 0;
    for_each_face(space, boundary, fe_face, [&](const auto &) {
      for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
        local += fe_face.JxW(q);
    });
    total_area = Utilities::MPI::sum(local, space.communicator);
  }

  void DeadSurfaceTraction::assemble(const Tensor<1, 3>              &traction,
                                     const AffineConstraints<double> &constraints,
                                     TrilinosWrappers::MPI::Vector   &rhs) const
  {
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                            update_values | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = space.fe->n_dofs_per_cell();
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    for_each_face(space, boundary, fe_face, [&](const auto &cell) {
      cell_rhs = 0;
      for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
        for (unsigned int i = 0; i < n; ++i)
          cell_rhs(i) += (fe_face[displacement].value(i, q) * traction) * fe_face.JxW(q);
      cell->get_dof_indices(dofs);
      constraints.distribute_local_to_global(cell_rhs, dofs, rhs);
    });
  }
} // namespace softchain::fem
