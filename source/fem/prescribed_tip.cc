#include <softchain/data/input_error.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/prescribed_tip.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <cmath>
#include <map>

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
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(*space.mapping, space.dof_handler, support_points);
    IndexSet all_tip(space.dof_handler.n_dofs());
    for (unsigned int c = 0; c < 3; ++c)
      {
        std::vector<bool> mask(3, false);
        mask[c] = true;
        const IndexSet tip =
          DoFTools::extract_boundary_dofs(space.dof_handler, ComponentMask(mask), {boundary::tip});
        all_tip.add_indices(tip);
        for (const auto index : tip)
          if (space.owned_dofs.is_element(index))
            owned_tip_dofs.push_back({index, c, support_points.at(index)});
      }
    if (Utilities::MPI::sum(owned_tip_dofs.size(), communicator) == 0)
      throw data::InputError("a prescribed tip motion needs the mesh's physical group 'tip'");
    held.reinit(space.relevant_dofs);
    for (const auto index : all_tip)
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
    for (const TipDof &dof : owned_tip_dofs)
      {
        // The node's position: X plus its three displacement components,
        // found among the DoFs at the same support point.
        Point<3> y = dof.support_point;
        for (const TipDof &other : owned_tip_dofs)
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
        const TipDof      &dof    = owned_tip_dofs[k];
        const Tensor<1, 3> target = centre_ + rotate(motion.rotation, anchored[k] - centre_) +
                                    motion.translation;
        owned_u[dof.index] = target[dof.component] - dof.support_point[dof.component];
      }
    owned_u.compress(VectorOperation::insert);
  }
} // namespace softchain::fem
