#pragma once
// ChainEquilibrium: static equilibrium of a ChainModel under a ChainLoad,
//   r(q) = K q - J_p p - J(q)^T f = 0                     (paper, Sec. III-C)
// solved by Newton's method with the exact tangent dr/dq.
//
// The problem is conservative: r is the gradient of the potential energy
//   U(q) = 1/2 q^T K q - (J_p p)^T q - sum_k f_k . x_k(q)
// (dead forces f_k at the material points x_k). Hence J(q)^T f is taken as the
// generalised force of the Euler angles, Q_{i,alpha} = a_{i,alpha} . M_i with
// M_i = sum_{k distal to i} (x_k - c_i) x f_k the moment about joint i: the
// reduction's joint-frame torque to first order, exactly so in planar bending.
// With a JointForceLaw the joints it covers replace K_j q_j by J_p,j p +
// T_j(q_j - q_p,j) (q_p = K^-1 J_p p), 1/2 q_j^T K_j q_j by J_p,j p . q_j +
// W_j(q_j - q_p,j) and K_j by the law's symmetric tangent dT_j/dq_j: the
// problem stays conservative and H symmetric, in ChainTangent's form.
// The tangent H = dr/dq = K - dQ/dq is the Hessian of U, symmetric:
//   dQ_{j,alpha}/dq_{l,beta} = [(l,beta) before (j,alpha)] (a_{l,beta} x a_{j,alpha}) . M_j
//                              + a_{j,alpha} . B_max(j,l) a_{l,beta},
//   B_m = A_m - tr(A_m) I,  A_m = sum_{k distal to m} (x_k - c_m) f_k^T,
// from da_{j,alpha} = a_{l,beta} x a_{j,alpha} and d(x_k - c_j) = a_{l,beta} x (x_k - c_max(j,l)).
//
// H has the block semiseparable form of ChainTangent, which solves the
// Newton system in O(n).
//
// Twist pivots (KinematicChain::with_twist_offsets): psi of joint j turns
// about an axis through s_j, not c_j. Then Q_{j,psi} = a_{j,psi} . M_j^s with
// the moment about s_j, M_j^s = M_j + d_j x F_j (d_j = c_j - s_j, F_j the sum
// of the loads distal to j), and in the formulas above the psi row takes
// M_j^s and B_j^s = A_j^s - tr(A_j^s) I, A_j^s = A_j + d_j F_j^T, in place of
// M_j and B_j: the derivation holds for any pivot of each angle, since the
// difference of two points distal to a rotation does not depend on its pivot.
//
// Links that shift as their joint turns (KinematicChain::assign_link_shift):
// phi of joint j turns about the rolling pivot p_j = c_j + a_phi x R_j g_j,
// and its row takes M and B about p_j as psi's takes them about s_j. That
// pivot moves rigidly with every angle before phi_j, so the formulas hold,
// but with phi_j itself it turns, d p_j / d phi_j = -R_j g_j, which adds
// a_phi . (R_j g_j x F_j) to dQ_{j,phi}/dphi_j (the potential is still
// -sum f . x(q), and H symmetric).
//
// Globalisation, so that bending through 180 deg and beyond converges from
// rest: the Newton step is capped at max_step_angle per angle; where H is not
// positive definite (post-buckling) it is shifted, H + mu I, which keeps the
// step a descent direction of U; a backtracking line search then requires U
// to decrease (Armijo). Converged when |r|_inf <= tolerance * (|K q|_inf +
// |J_p p|_inf + |J^T f|_inf). A load it cannot equilibrate within
// max_iterations, or whose equilibrium leaves the chain's range of validity
// (|theta_i| < 90 deg where the Euler convention is regular, |psi_i|, |phi_i|
// <= 180 deg since the reduction reads angles in that range), or that is
// unstable (H not positive definite there; checked when no Newton step was
// needed or the last one had to shift H, e.g. a straight finger under an
// axial compressive load beyond buckling), is reported as failed with the
// reason; the pose is then not an answer.
//
// Contact (ChainContact): with obstacles in the load, the model's collision
// surface adds its penalty energy U_c to U, its point forces to J^T f, and
// to H a sum of rows of single links, V^T diag(w) V. Each Newton step
// minimises the quadratic model of U with the penalties of the surface
// points near an obstacle linearised, by an active set over them
// (contact_direction in the source). The rows of a pass (touching points,
// their curvatures, the skins' and the friction's rows) are gathered into
// each link's 6 x 6 stiffness (LinkWrenchStiffness), added to H's dense
// form in O(n^2) and factored by Cholesky: for a finger's few dozen angles
// this costs less than the rows would one by one. A solve from rest starts
// short of the first touch along the pressure's own shape (so that it never
// starts deep inside an obstacle). The stability check then factors the
// whole tangent. Friction acts through the load's stick anchors
// (ChainLoad::anchors, CoulombFriction): a load on an obstacle with friction
// but without anchors is solved as if frictionless -- the first solve of a
// load step; FrictionalLoadPath follows a frictional load from rest.
#include <softchain/chain/chain_contact.h>
#include <softchain/chain/chain_load.h>
#include <softchain/chain/chain_model.h>

#include <softchain/chain/chain_tangent.h>
#include <softchain/chain/link_wrench_stiffness.h>

#include <Eigen/Core>
#include <string>

namespace softchain::chain
{
  struct EquilibriumSettings
  {
    double tolerance      = 1e-10; // relative residual
    int    max_iterations = 50;
    double max_step_angle = 1.5;   // rad per angle and Newton step
    double contact_stiffness = 1e5; // k_c of ChainContact, N/m per surface point
  };

  struct Equilibrium
  {
    Eigen::VectorXd angles;        // q at the last iterate
    bool            converged = false;
    int             iterations = 0; // Newton steps taken
    double          residual = 0.0; // relative residual at `angles`
    std::string     failure;        // why not converged (empty if converged)
  };

  class ChainEquilibrium
  {
  public:
    // Keeps a reference to `model`, which must outlive the solver.
    explicit ChainEquilibrium(const ChainModel &model, EquilibriumSettings settings = {});

    // Equilibrium from the pressure's own equilibrium K q = J_p p (linear:
    // q = K^-1 J_p p, the answer when there are no forces), or from `start`
    // (warm start, e.g. the previous pressure of a sweep).
    Equilibrium solve(const ChainLoad &load);
    Equilibrium solve(const ChainLoad &load, const Eigen::VectorXd &start);
    // The relative residual at which a solve stops (EquilibriumSettings);
    // std::invalid_argument unless positive.
    double tolerance() const { return settings_.tolerance; }
    void   set_tolerance(double tolerance);

    // The pieces, for tests and for the dynamic step: set a load, then
    // evaluate U, r and H at q.
    void                   set_load(const ChainLoad &load);
    double                 energy(const Eigen::VectorXd &q);
    Eigen::VectorXd        residual(const Eigen::VectorXd &q);
    Eigen::MatrixXd        tangent(const Eigen::VectorXd &q);
    // The (shifted, capped) Newton step at q, by ChainTangent's O(n) solve.
    Eigen::VectorXd        newton_step(const Eigen::VectorXd &q);
    // Pose of the last evaluation, and the geometry it belongs to: the
    // model's at the pressure of the last set_load (ChainModel::chain_at).
    const ChainPose      &pose() const { return pose_; }
    const KinematicChain &chain() const { return chain_; }
    // The contact of the last evaluation: touching points, obstacle wrenches.
    const ChainContact   &contact() const { return contact_; }

  private:
    struct AttachedLoad
    {
      int             link;
      Eigen::Vector3d reference_point;
      Eigen::Vector3d force;
    };

    Equilibrium iterate(const Eigen::VectorXd &start);
    Eigen::VectorXd before_first_contact(const Eigen::VectorXd &free);
    void   evaluate(const Eigen::VectorXd &q);
    double evaluate_springs(const Eigen::VectorXd &q);
    void   accumulate_distal_loads();
    void   add_contact_tangent(Eigen::MatrixXd &dense) const;
    bool   touching() const; // a touching point or a friction anchor at the last evaluation
    Eigen::Vector3d moment_about(int m, int alpha) const; // M_m about the pivot of angle alpha
    void   prepare_tangent();
    bool   converged() const;
    double relative_residual() const;
    void   newton_direction();
    void   contact_direction();
    // The step of the quadratic model with the candidates within search_margin_.
    void   model_direction();
    void   settle_active_set(bool curvature, std::vector<char> &active);
    double model_step(const Eigen::VectorXd &d, const std::vector<double> &ds, const Eigen::VectorXd &dd,
                      const std::vector<double> &dds, bool curvature);
    void   contact_step(const std::vector<char> &active, bool curvature);
    void   dense_solve(const Eigen::VectorXd &b);
    void   add_skin_rows(const std::vector<char> &active);
    void   link_twists(const Eigen::VectorXd &d, std::vector<LinkWrenchStiffness::Vector6d> &twists) const;
    // A bound of the distance any surface point moved in the step `step`
    // (to first order): over the links, |v_b + w_b x c| + |w_b| r of the
    // sphere (c, r) that holds all the link's points.
    double surface_motion(const Eigen::VectorXd &step);
    double sphere_motion(int node) const;
    void   next_search_margin(const Eigen::VectorXd &step, double fall);
    bool   predict_active_set(const std::vector<LinkWrenchStiffness::Vector6d> &twists, const std::vector<double> &ds,
                              std::vector<char> &active) const;
    void   limit_surface_motion();
    bool   line_search(Eigen::VectorXd &q);
    std::string range_violation(const Eigen::VectorXd &q) const;
    std::string instability();

    const ChainModel   &model_;
    EquilibriumSettings settings_;
    KinematicChain      chain_; // the model's geometry at the load's pressure

    // Load (set_load)
    Eigen::VectorXd           stiffness_;       // diag K
    Eigen::VectorXd           pressure_torque_; // J_p p
    Eigen::VectorXd           pressure_angles_; // q_p = K^-1 J_p p, the pressure-only state
    std::vector<JointForceLaw::Blend> force_law_; // per joint at the load's pressure; empty: linear
    std::vector<AttachedLoad> loads_;           // sorted by link
    ChainContact              contact_;         // the load's obstacles
    LinkWrenchStiffness       link_model_;      // a contact step's rows and forces, per link
    // The widest reach of the active set's candidates: 5 % of the chain's
    // length (on P10 the fastest of 2, 5 and 10 % at the same iterations,
    // with every point within it a candidate at every step).
    double                    contact_margin_ = 0.0;
    // The reach of the step's candidates (contact_direction): all of
    // contact_margin_ at a load's first step, then a few times the surface's
    // motion expected of the next (next_search_margin), so that
    // the steps that settle an equilibrium (a fraction of a millimetre,
    // then microns) carry the points that can touch in them, not every
    // point within 5 % of the length; widened up to contact_margin_ where
    // the step moves farther.
    double                    search_margin_ = 0.0;
    std::vector<ChainContact::Touch> near_;     // the step's active-set candidates
    std::vector<LinkWrenchStiffness::Vector6d> near_rows_; // their normal rows g_c (LinkWrenchStiffness)
    Eigen::VectorXd           gaps_;            // their gaps g_c
    Eigen::VectorXd           free_residual_;   // r_f of the step's model
    std::vector<LinkWrenchStiffness::Vector6d> twists_; // each link's twist (w_b, v_b) under a step
    std::vector<LinkWrenchStiffness::Vector6d> step_twists_; // and under a pass's change of it
    std::vector<double>       h0_, h1_;         // each candidate's predicted gap along a pass, h0 + t h1
    std::vector<ChainContact::LinkRow> curvature_rows_; // the touching points' curvature rows
    std::vector<ChainContact::LinkRow> friction_rows_;  // the friction's rows
    // The skins of the step's model (ChainContact::Skin), the alignment
    // a_c = n_c . d_b of each candidate, and per skin row the prediction of
    // its displacement's change, -(gamma_b + u_b d) / D_b.
    std::vector<ChainContact::Skin> skins_;
    std::vector<int>          skin_of_link_;    // index into skins_ per link, -1: none
    Eigen::VectorXd           alignment_;
    struct SkinPrediction
    {
      int                           link;
      double                        gamma, D;
      LinkWrenchStiffness::Vector6d u;
    };
    std::vector<SkinPrediction> skin_predictions_;
    Eigen::MatrixXd           dense_tangent_;   // H, dense, for the step's solves

    // State of the last evaluation
    Eigen::VectorXd              spring_torque_; // the joints' spring torques
    std::vector<Eigen::Matrix3d> spring_tangent_; // their derivatives, K's diagonal blocks
    ChainPose                    pose_;
    std::vector<Eigen::Vector3d> moment_;       // M_i
    std::vector<Eigen::Matrix3d> moment_gradient_; // B_i
    std::vector<Eigen::Vector3d> distal_force_;    // F_i = sum of the loads distal to i
    Eigen::VectorXd              generalised_force_; // Q = J^T f
    Eigen::VectorXd              residual_;
    double                       residual_scale_ = 0.0;   // |K q| + |J_p p| + |Q|
    double                       energy_ = 0.0;
    double                       energy_magnitude_ = 0.0; // sum of |terms| of U
    ChainTangent                 tangent_;
    Eigen::VectorXd              direction_;
    Eigen::VectorXd              line_start_; // the line search's start
    bool                         shifted_ = false; // the last Newton step shifted H
  };
} // namespace softchain::chain
