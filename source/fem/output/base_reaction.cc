#include <softchain/data/input_error.h>
#include <softchain/fem/base_reaction.h>
#include <softchain/fem/boundary_ids.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // Area-weighted centroid of the faces with boundary id `base`.
    Point<3> base_centroid(const FiniteElementSpace &space)
    {
      FEFaceValues<3> fe_face(*space.mapping, *space.fe, space.face_quadrature,
                              update_quadrature_points | update_JxW_values);
      Tensor<1, 3> moment;
      double       area = 0;
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary::base)
              {
                fe_face.reinit(cell, f);
                for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
                  {
                    moment += fe_face.JxW(q) * fe_face.quadrature_point(q);
                    area += fe_face.JxW(q);
                  }
              }
      moment = Utilities::MPI::sum(moment, space.communicator);
      area   = Utilities::MPI::sum(area, space.communicator);
      if (!(area > 0))
        throw data::InputError("the mesh has no face in the physical group 'base', whose "
                               "reaction the base wrench is");
      return Point<3>(moment / area);
    }
  } // namespace

  BaseReaction::BaseReaction(const FiniteElementSpace &space)
    : communicator(space.communicator)
    , owned_base_dofs(owned_boundary_dofs(space, boundary::base))
    , centroid_(base_centroid(space))
  {}

  BaseReaction::Wrench
  BaseReaction::wrench(const TrilinosWrappers::MPI::Vector &support_forces) const
  {
    Wrench w;
    for (const BoundaryDof &dof : owned_base_dofs)
      {
        Tensor<1, 3> f;
        f[dof.component] = support_forces[dof.index];
        w.force += f;
        w.moment += cross_product_3d(dof.support_point - centroid_, f);
      }
    w.force  = Utilities::MPI::sum(w.force, communicator);
    w.moment = Utilities::MPI::sum(w.moment, communicator);
    return w;
  }
} // namespace softchain::fem
