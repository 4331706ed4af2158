#pragma once
// PrescribedTip: a rigid motion imposed on the tip face (the paper's
// validation, Sec. IV-B: the fingertip moved by a point contact, here held
// as a whole), relative to the state in which it was first prescribed (e.g.
// the inflated finger):
//   y_i -> c + R(theta) (y_i - c) + t,
// y_i the positions of the tip face's DoF support points at that state, c
// their mean, R(theta) the rotation by the rotation vector theta (axis times
// angle, Rodrigues), t the translation. The tip DoFs are set to the motion
// at each load step and held there by homogeneous constraints during Newton;
// their reactions are the contact wrench.
#include <softchain/fem/boundary_dofs.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace softchain::fem
{
  struct TipMotion
  {
    dealii::Tensor<1, 3> translation; // t, m
    dealii::Tensor<1, 3> rotation;    // theta, rad (axis times angle)
  };

  class PrescribedTip
  {
  public:
    // Finds the tip DoFs (boundary id `tip`) and builds the constraints:
    // those of `space` plus every tip DoF held (collective).
    explicit PrescribedTip(const FiniteElementSpace &space);

    // Takes the tip's current positions (`u` with ghosts) as the state the
    // motions are relative to.
    void anchor(const dealii::TrilinosWrappers::MPI::Vector &u);
    // Writes the displacement of `motion` into the tip DoFs of `owned_u`.
    void apply(const TipMotion &motion, dealii::TrilinosWrappers::MPI::Vector &owned_u) const;

    // The space's constraints and the tip DoFs held (homogeneous).
    const dealii::AffineConstraints<double> &constraints() const { return held; }
    // c: the mean anchored position of the tip DoFs' support points.
    const dealii::Point<3> &centre() const { return centre_; }

  private:
    MPI_Comm                          communicator;
    std::vector<BoundaryDof>          owned_tip_dofs;
    std::vector<dealii::Point<3>>     anchored; // per owned tip DoF: its node's y
    dealii::Point<3>                  centre_;
    dealii::AffineConstraints<double> held;
  };
} // namespace softchain::fem
