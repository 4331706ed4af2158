#include <softchain/fem/boundary_average.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

namespace softchain::fem
{
  using namespace dealii;

  Tensor<1, 3> mean_boundary_displacement(const FiniteElementSpace            &space,
                                          const TrilinosWrappers::MPI::Vector &u,
                                          const types::boundary_id             boundary)
  {
    FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                            update_values | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 3>>        u_q(space.face_quadrature.size());
    Tensor<1, 3>                     integral;
    double                           area = 0;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary)
            {
              fe_face.reinit(cell, f);
              fe_face[displacement].get_function_values(u, u_q);
              for (unsigned int q = 0; q < u_q.size(); ++q)
                {
                  integral += u_q[q] * fe_face.JxW(q);
                  area += fe_face.JxW(q);
                }
            }
    return Utilities::MPI::sum(integral, space.communicator) /
           Utilities::MPI::sum(area, space.communicator);
  }
} // namespace softchain::fem
