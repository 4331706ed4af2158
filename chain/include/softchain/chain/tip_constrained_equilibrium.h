#pragma once
// TipConstrainedEquilibrium: the chain's static equilibrium with its tip point
// held at a prescribed position, as a point contact holds a fingertip (the
// chopstick of the paper's validation, Sec. IV-B). Unknowns: the joint angles
// q and the contact force f_c on the tip (the Lagrange multiplier of the
// position constraint):
//   r(q) - J(q)^T f_c = 0,     x_tip(q) - x* = 0,
// r the residual of ChainEquilibrium under the other loads (pressure, point
// loads) and J = dx_tip/dq, whose column (i, alpha) is a_{i,alpha} x (x_tip - c_i)
// (kinematic_chain.h). Newton's method on (q, f_c) with the exact Jacobian
//   [ H(q; f_c)  -J^T ] [ dq  ]     [ r - J^T f_c ]
//   [ J           0   ] [ df_c] = - [ x_tip - x*  ],
// H(q; f_c) being ChainEquilibrium's tangent with f_c added as a dead point
// load at the tip (its geometric stiffness). Where J is rank deficient -- a
// straight chain cannot move its tip along its axis to first order, a single
// rigid link never -- the system is solved in the least-squares, minimum-norm
// sense, so that the force component the kinematics cannot resist (along a
// straight chain) stays undetermined at zero increment instead of blowing up.
// Converged when |r - J^T f_c|_inf <= tolerance * (|K q|_inf + |J_p p|_inf +
// |J^T f_c|_inf) and |x_tip - x*|_inf <= tolerance * (chain length).
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/chain_load.h>
#include <softchain/chain/chain_model.h>

#include <Eigen/Core>
#include <string>

namespace softchain::chain
{
  struct ConstrainedEquilibrium
  {
    Eigen::VectorXd angles;                                  // q at the last iterate
    Eigen::Vector3d contact_force = Eigen::Vector3d::Zero(); // f_c on the tip, N, world
    bool            converged     = false;
    int             iterations    = 0;
    std::string     failure; // why not converged (empty if converged)
  };

  class TipConstrainedEquilibrium
  {
  public:
    // Keeps a reference to `model`, which must outlive the solver.
    explicit TipConstrainedEquilibrium(const ChainModel &model, EquilibriumSettings settings = {});

    // Equilibrium under `load` with the tip at `tip_target` (world, m),
    // Newton from `start` (e.g. the free equilibrium, or the previous target
    // of a prescribed motion).
    ConstrainedEquilibrium solve(const ChainLoad &load, const Eigen::Vector3d &tip_target,
                                 const Eigen::VectorXd &start);

    // `load` plus the contact force as a dead point load at the tip point.
    ChainLoad with_contact(const ChainLoad &load, const Eigen::Vector3d &contact_force) const;
    // Pose of the last evaluation.
    const ChainPose &pose() const { return equilibrium_.pose(); }

  private:
    // dx_tip/dq at pose(): 3 x (3 n_joints).
    Eigen::MatrixXd tip_jacobian() const;
    double          residual_scale(const ChainLoad &load, const Eigen::VectorXd &q,
                                   const Eigen::VectorXd &contact_torque) const;

    const ChainModel   &model_;
    EquilibriumSettings settings_;
    ChainEquilibrium    equilibrium_;
  };
} // namespace softchain::chain
