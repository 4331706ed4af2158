#pragma once
// TipConstrainedEquilibrium: the chain's static equilibrium with its tip held,
// as a point contact holds a fingertip (the chopstick of the paper's
// validation, Sec. IV-B): the tip point at a prescribed position and, if
// given, the tip frame (last link) at a prescribed rotation, as the FEM's
// PrescribedTip holds the whole tip face. Unknowns: the joint angles q, the
// contact force f_c on the tip and, with a rotation, the contact couple m_c
// (the Lagrange multipliers of the constraints):
//   r(q) - J(q)^T f_c - W(q)^T m_c = 0,   x_tip(q) + c f_c + d - x* = 0,
//   log(R_tip(q) R*^T) = 0,
// r the residual of ChainEquilibrium under the other loads (pressure, point
// loads), c the links' compliance and d the other loads' deflection of the
// tip (LinkCompliance; both 0 with links rigid under forces: the links then
// give c f_c in series with the joints),
// J = dx_tip/dq with column (i, alpha) a_{i,alpha} x (x_tip - c_i),
// W = [a_{i,alpha}] the tip's angular velocity Jacobian (kinematic_chain.h)
// and log the rotation vector. Newton's method on (q, f_c, m_c):
//   [ H(q; f_c) - G(q; m_c)  -J^T  -W^T ] [ dq  ]     [ r - J^T f_c - W^T m_c ]
//   [ J                        c I   0  ] [ df_c] = - [ x_tip + c f_c + d - x* ]
//   [ W                        0     0  ] [ dm_c]     [ log(R_tip R*^T)      ]
// H(q; f_c) is ChainEquilibrium's tangent with f_c added as a dead point load
// at the tip (its geometric stiffness), G the derivative of W^T m_c for a
// dead couple, G_{(j,alpha),(l,beta)} = [(l,beta) before (j,alpha)]
// (a_{l,beta} x a_{j,alpha}) . m_c, from da_{j,alpha}/dq_{l,beta} =
// a_{l,beta} x a_{j,alpha}. W is the exact derivative of the rotation
// constraint at the solution (log(R) = 0) and a first-order one elsewhere,
// so Newton still converges quadratically. Where the Jacobian is rank
// deficient and the links are rigid -- a straight chain cannot move its tip
// along its axis to first order, a single rigid link never -- the system is
// solved in the
// least-squares, minimum-norm sense, so that the force component the
// kinematics cannot resist (along a straight chain) stays undetermined at
// zero increment instead of blowing up. Converged when
// |r - J^T f_c - W^T m_c|_inf <= tolerance * (|K q|_inf + |J_p p|_inf +
// |J^T f_c|_inf + |W^T m_c|_inf), |x_tip + c f_c + d - x*|_inf <= tolerance
// * (chain length) and |log(R_tip R*^T)|_inf <= tolerance.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/chain_load.h>
#include <softchain/chain/chain_model.h>

#include <Eigen/Core>
#include <optional>
#include <string>

namespace softchain::chain
{
  struct ConstrainedEquilibrium
  {
    Eigen::VectorXd angles;                                  // q at the last iterate
    Eigen::Vector3d contact_force  = Eigen::Vector3d::Zero(); // f_c on the tip, N, world
    Eigen::Vector3d contact_moment = Eigen::Vector3d::Zero(); // m_c, N m, world (0: point held)
    bool            converged     = false;
    int             iterations    = 0;
    std::string     failure; // why not converged (empty if converged)
  };

  // Where the tip is held: its point and, optionally, its frame.
  struct TipTarget
  {
    Eigen::Vector3d                position = Eigen::Vector3d::Zero(); // x*, m, world
    std::optional<Eigen::Matrix3d> rotation; // R*, the last link's; none: the point only
  };

  // W at `pose`: the world joint axes a_{i,alpha} as columns, 3 x (3 n_joints),
  // the tip's angular velocity Jacobian.
  Eigen::MatrixXd angular_jacobian(const ChainPose &pose);
  // G at `pose`: d(W^T m)/dq, the generalised force of a dead couple m
  // differentiated (lower triangular: an axis moves with the angles before it).
  Eigen::MatrixXd dead_couple_stiffness(const ChainPose &pose, const Eigen::Vector3d &m);

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
    // The same with the tip frame held too if `target` has a rotation.
    ConstrainedEquilibrium solve(const ChainLoad &load, const TipTarget &target,
                                 const Eigen::VectorXd &start);

    // `load` plus the contact force as a dead point load at the tip point.
    ChainLoad with_contact(const ChainLoad &load, const Eigen::Vector3d &contact_force) const;
    // Pose of the last evaluation.
    const ChainPose &pose() const { return equilibrium_.pose(); }
    const KinematicChain &chain() const { return equilibrium_.chain(); }

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
