#pragma once
// BaseReaction: the wrench the finger exerts on its clamped base -- what a
// force/torque sensor under the base plate measures (the paper's validation,
// Sec. IV-B). With r = f_ext - f_int assembled without the Dirichlet
// constraint (QuasiStaticSolver::support_forces), the clamped DoFs hold the
// nodal forces on the support, and
//   F = sum_{base DoFs i} r_i e_c(i),   M = sum_i (X_i - O) x r_i e_c(i),
// X_i the DoF's support point (the base does not move), c(i) its component,
// O the centroid of the base face (area weighted, reference configuration).
// World axes are the base frame. At equilibrium the internal forces cancel
// over the body, so F and M equal the resultant of the external loads (for a
// closed cavity the follower pressure has none).
#include <softchain/fem/boundary_dofs.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace softchain::fem
{
  class BaseReaction
  {
  public:
    struct Wrench
    {
      dealii::Tensor<1, 3> force;  // N
      dealii::Tensor<1, 3> moment; // N m, about centroid()
    };

    // Finds the base DoFs (boundary id `base`), their support points and
    // the base face's centroid (collective on the space's communicator).
    explicit BaseReaction(const FiniteElementSpace &space);

    // The wrench of `support_forces` (collective).
    Wrench wrench(const dealii::TrilinosWrappers::MPI::Vector &support_forces) const;

    const dealii::Point<3> &centroid() const { return centroid_; }

  private:
    MPI_Comm                 communicator;
    std::vector<BoundaryDof> owned_base_dofs;
    dealii::Point<3>     centroid_;
  };
} // namespace softchain::fem
