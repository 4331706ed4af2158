#pragma once
// PrescribedTip: a motion imposed on the tip (the paper's validation, Sec.
// IV-B: the fingertip moved by a chopstick), relative to the state in which
// it was first prescribed (the anchor, e.g. the inflated finger). Two kinds:
//
// Face held: the tip face moves rigidly,
//   y_i -> c + R(theta) (y_i - c) + t,
// y_i the positions of the tip face's DoF support points at the anchor, c
// their mean, R(theta) the rotation by the rotation vector theta (axis times
// angle, Rodrigues), t the translation. The tip DoFs are set to the motion
// at each load step and held there by homogeneous constraints during Newton;
// their reactions are the contact wrench.
//
// Point contact: only the mean displacement of the tip face's DoFs moves,
// (1/n) sum_i u_{i,c} = (1/n) sum_i u0_{i,c} + t_c per component c (u0 at
// the anchor), a point contact spread over the face: the face turns and
// deforms freely, the contact transmits a force and no couple. Per
// component one tip DoF k (the lowest index) is eliminated by the linear
// constraint u_k = n m_c - sum_{i != k} u_i, which couples it to every tip
// DoF of its component (the system's sparsity pattern must allow that:
// coupled_dofs()).
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
    dealii::Tensor<1, 3> rotation;    // theta, rad (axis times angle); 0 for a point contact
    bool                 point_contact = false;
  };

  class PrescribedTip
  {
  public:
    // Finds the tip DoFs (boundary id `tip`) and builds the constraints:
    // those of `space` plus every tip DoF held, or the point contact's three
    // (collective).
    PrescribedTip(const FiniteElementSpace &space, bool point_contact);

    bool point_contact() const { return point_; }
    // Every tip DoF, all ranks (point contact: the DoFs its constraints
    // couple, which the matrix and the residual must be able to hold).
    const dealii::IndexSet &coupled_dofs() const { return all_tip_dofs; }

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
    bool                              point_;
    std::vector<BoundaryDof>          owned_tip_dofs;
    dealii::IndexSet                  all_tip_dofs;
    dealii::Tensor<1, 3>              anchored_mean; // mean tip displacement at the anchor
    std::vector<dealii::Point<3>>     anchored; // per owned tip DoF: its node's y
    dealii::Point<3>                  centre_;
    dealii::AffineConstraints<double> held;

    void hold_face(const FiniteElementSpace &space);
    void hold_mean(const FiniteElementSpace &space);
    void apply_mean(const TipMotion &motion, dealii::TrilinosWrappers::MPI::Vector &owned_u) const;
    // Mean of u over the tip DoFs, per component (collective).
    dealii::Tensor<1, 3> mean_displacement(const dealii::TrilinosWrappers::MPI::Vector &u) const;
  };
} // namespace softchain::fem
