#include <softchain/data/input_error.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/prescribed_tip.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // R(theta) v by Rodrigues' formula.
    Tensor<1, 3> rotate(const Tensor<1, 3> &theta, const Tensor<1, 3> &v)
    {
      const double angle = theta.norm();
      if (angle == 0.0)
        return v;
      const Tensor<1, 3> k = theta / angle;
      return std::cos(angle) * v + std::sin(angle) * cross_product_3d(k, v) +
             (1 - std::cos(angle)) * (k * v) * k;
    }
  } // namespace

  PrescribedTip::PrescribedTip(const FiniteElementSpace &space)
    : communicator(space.communicator)
    , owned_tip_dofs(owned_boundary_dofs(space, boundary::tip))
  {
    if (Utilities::MPI::sum(owned_tip_dofs.size(), communicator) == 0)
      throw data::InputError("a prescribed tip motion needs the mesh's physical group 'tip'");
    held.reinit(space.relevant_dofs);
    // Every relevant tip DoF (ghosts too, so that each rank's constraints
    // hold the DoFs its cells touch).
    for (const auto index :
         DoFTools::extract_boundary_dofs(space.dof_handler, ComponentMask(), {boundary::tip}))
      if (space.relevant_dofs.is_element(index) && !space.fixed_dofs.is_constrained(index))
        held.add_line(index);
    held.merge(space.fixed_dofs, AffineConstraints<double>::left_object_wins);
    held.close();
  }

  void PrescribedTip::anchor(const TrilinosWrappers::MPI::Vector &u)
  {
    anchored.clear();
    Tensor<1, 3> sum;
    double       n = 0;
    for (const BoundaryDof &dof : owned_tip_dofs)
      {
        // The node's position: X plus its three displacement components,
        // found among the DoFs at the same support point.
        Point<3> y = dof.support_point;
        for (const BoundaryDof &other : owned_tip_dofs)
          if (other.support_point.distance(dof.support_point) < 1e-12)
            y[other.component] += u[other.index];
        anchored.push_back(y);
        if (dof.component == 0)
          {
            sum += y;
            n += 1;
          }
      }
    centre_ = Point<3>(Utilities::MPI::sum(sum, communicator) / Utilities::MPI::sum(n, communicator));
  }

  void PrescribedTip::apply(const TipMotion &motion, TrilinosWrappers::MPI::Vector &owned_u) const
  {
    for (std::size_t k = 0; k < owned_tip_dofs.size(); ++k)
      {
        const BoundaryDof &dof    = owned_tip_dofs[k];
        const Tensor<1, 3> target = centre_ + rotate(motion.rotation, anchored[k] - centre_) +
                                    motion.translation;
        owned_u[dof.index] = target[dof.component] - dof.support_point[dof.component];
      }
    owned_u.compress(VectorOperation::insert);
  }
} // namespace softchain::fem
