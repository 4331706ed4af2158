#include <softchain/data/input_error.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/prescribed_tip.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // u_i at a DoF this rank owns, in the Trilinos vector's own storage: a
    // write there needs no communication. (Element access followed by
    // compress() is not symmetric: compress() communicates only on the ranks
    // that accessed elements, so a rank without tip DoFs went on while one
    // with them waited in it, and a sweep's tip motions hung on two ranks.)
    double &owned_entry(TrilinosWrappers::MPI::Vector &u, const types::global_dof_index i)
    {
      Epetra_FEVector &v     = u.trilinos_vector();
      const int        local = v.Map().LID(static_cast<TrilinosWrappers::types::int_type>(i));
      Assert(local >= 0, ExcMessage("not a locally owned DoF"));
      return v[0][local];
    }

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

  PrescribedTip::PrescribedTip(const FiniteElementSpace &space, const bool point_contact)
    : communicator(space.communicator)
    , point_(point_contact)
    , owned_tip_dofs(owned_boundary_dofs(space, boundary::tip))
    , all_tip_dofs(space.dof_handler.n_dofs())
  {
    if (Utilities::MPI::sum(owned_tip_dofs.size(), communicator) == 0)
      throw data::InputError("a prescribed tip motion needs the mesh's physical group 'tip'");
    if (point_)
      hold_mean(space);
    else
      hold_face(space);
    held.close();
  }

  // Every relevant tip DoF held (ghosts too, so that each rank's constraints
  // hold the DoFs its cells touch). The lines are indexed globally, as the
  // space's fixed DoFs they are merged with (those of every rank: merged
  // into constraints over this rank's relevant DoFs, another rank's clamped
  // DoFs crashed the merge).
  void PrescribedTip::hold_face(const FiniteElementSpace &space)
  {
    held.clear();
    for (const auto index :
         DoFTools::extract_boundary_dofs(space.dof_handler, ComponentMask(), {boundary::tip}))
      if (space.relevant_dofs.is_element(index) && !space.fixed_dofs.is_constrained(index))
        held.add_line(index);
    held.merge(space.fixed_dofs, AffineConstraints<double>::left_object_wins);
  }

  // Per component, the lowest tip DoF k expressed by the others:
  // u_k = -sum_{i != k} u_i (+ the mean that apply() keeps). The lines'
  // entries reach tip DoFs of other ranks, so the constraints are indexed
  // globally (no local index set), like the space's fixed DoFs.
  void PrescribedTip::hold_mean(const FiniteElementSpace &space)
  {
    std::vector<std::pair<types::global_dof_index, unsigned int>> mine;
    for (const BoundaryDof &dof : owned_tip_dofs)
      mine.emplace_back(dof.index, dof.component);
    std::array<std::vector<types::global_dof_index>, 3> of_component;
    for (const auto &list : Utilities::MPI::all_gather(communicator, mine))
      for (const auto &[index, component] : list)
        of_component[component].push_back(index);
    for (auto &dofs : of_component)
      {
        std::sort(dofs.begin(), dofs.end());
        all_tip_dofs.add_indices(dofs.begin(), dofs.end());
      }
    all_tip_dofs.compress();
    held.clear(); // lines by global index, as the space's fixed DoFs (every rank's)
    held.merge(space.fixed_dofs);
    for (const auto &dofs : of_component)
      {
        const types::global_dof_index k = dofs.front();
        if (!space.relevant_dofs.is_element(k))
          continue;
        held.add_line(k);
        for (std::size_t j = 1; j < dofs.size(); ++j)
          held.add_entry(k, dofs[j], -1.0);
      }
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
    anchored_mean = mean_displacement(u);
  }

  Tensor<1, 3> PrescribedTip::mean_displacement(const TrilinosWrappers::MPI::Vector &u) const
  {
    Tensor<1, 3> sum, count;
    for (const BoundaryDof &dof : owned_tip_dofs)
      {
        sum[dof.component] += u[dof.index];
        count[dof.component] += 1;
      }
    sum   = Utilities::MPI::sum(sum, communicator);
    count = Utilities::MPI::sum(count, communicator);
    for (unsigned int c = 0; c < 3; ++c)
      sum[c] /= count[c];
    return sum;
  }

  void PrescribedTip::apply(const TipMotion &motion, TrilinosWrappers::MPI::Vector &owned_u) const
  {
    if (point_)
      return apply_mean(motion, owned_u);
    for (std::size_t k = 0; k < owned_tip_dofs.size(); ++k)
      {
        const BoundaryDof &dof    = owned_tip_dofs[k];
        const Tensor<1, 3> target = centre_ + rotate(motion.rotation, anchored[k] - centre_) +
                                    motion.translation;
        owned_entry(owned_u, dof.index) = target[dof.component] - dof.support_point[dof.component];
      }
  }

  // Every tip DoF shifted by the same amount per component, so that the
  // mean moves where the motion puts it (a smooth start for Newton).
  void PrescribedTip::apply_mean(const TipMotion &motion, TrilinosWrappers::MPI::Vector &owned_u) const
  {
    const Tensor<1, 3> shift = anchored_mean + motion.translation - mean_displacement(owned_u);
    for (const BoundaryDof &dof : owned_tip_dofs)
      owned_entry(owned_u, dof.index) += shift[dof.component];
  }
} // namespace softchain::fem
