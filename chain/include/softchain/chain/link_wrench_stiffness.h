#pragma once
// LinkWrenchStiffness: forces and stiffnesses that act on the chain through
// its rigid links, gathered link by link and mapped to the angles once.
//
// A point x of link b moves with the link's twist t_b = (w_b, v_b) (angular
// velocity, and the velocity of the link's point at the world origin):
//     dx = v_b + w_b x x,   so   e . dx = g^T t_b,   g = (x x e, e),
// g being the wrench (moment about the origin, force) of a unit force along
// e at x. The twist is the sum of the turns of the joints up to b,
//     t_b = sum_{i <= b, alpha} xi_{i,alpha} dq_{i,alpha},
//     xi_{i,alpha} = (a_{i,alpha}, p_{i,alpha} x a_{i,alpha}),
// a_{i,alpha} the axis and p_{i,alpha} the pivot of angle (i, alpha)
// (s_i for psi, c_i otherwise; KinematicChain). So a row g^T J_b of one
// link (a touching point's normal, a round obstacle's curvature, a friction
// direction, a skin; ChainContact) with weight w, and a force along it,
// add to the angles' tangent and generalised force
//     sum_b J_b^T G_b J_b,   G_b = sum_{rows of b} w g g^T     (6 x 6),
//     sum_b J_b^T h_b,       h_b = sum_{forces of b} s g.
// J_b's columns are the xi of the joints up to b, the same for every link
// beyond them, so the (j, i) block (i <= j) of the first is
//     Xi_j^T S_j Xi_i,   S_j = sum_{b >= j} G_b,
// and the generalised force of angle (i, alpha) is xi_{i,alpha}^T sum_{b >= i} h_b:
// O(n^2) and O(n) work for any number of rows, where one n-long row per
// point costs O(n^2) per row (a grasp touches with a hundred points).
#include <softchain/chain/kinematic_chain.h>

#include <Eigen/Core>

#include <vector>

namespace softchain::chain
{
  class LinkWrenchStiffness
  {
  public:
    using Vector6d = Eigen::Matrix<double, 6, 1>;
    using Matrix6d = Eigen::Matrix<double, 6, 6>;

    // g = (x x e, e): the row of the motion along e of the point x.
    static Vector6d point_row(const Eigen::Vector3d &x, const Eigen::Vector3d &e)
    {
      Vector6d g;
      g << x.cross(e), e;
      return g;
    }

    // Nothing on any of `n_links` links.
    void reset(int n_links);
    // G_b += w g g^T.
    void add_row(int link, const Vector6d &g, double weight);
    // h_b += s g.
    void add_force(int link, const Vector6d &g, double scale);

    // + sum_b J_b^T G_b J_b at `pose` to the lower triangle of `dense`
    // (n_angles square), or to all of it.
    void add_to_lower(const ChainPose &pose, Eigen::MatrixXd &dense) const;
    void add_to(const ChainPose &pose, Eigen::MatrixXd &dense) const;
    // + sum_b J_b^T h_b at `pose` to `generalised` (n_angles).
    void add_generalised_force(const ChainPose &pose, Eigen::VectorXd &generalised) const;

  private:
    // Xi_i of every joint at `pose` into twists_ (6 x n_angles).
    void joint_twists(const ChainPose &pose) const;
    // The lower triangle's blocks into `dense`, and if `mirror` the upper's too.
    void add_blocks(const ChainPose &pose, Eigen::MatrixXd &dense, bool mirror) const;

    std::vector<Matrix6d>   stiffness_; // G_b
    std::vector<Vector6d>   force_;     // h_b
    int                     last_stiff_ = -1, last_force_ = -1; // the most distal link with any
    mutable Eigen::Matrix<double, 6, Eigen::Dynamic> twists_;
  };
} // namespace softchain::chain
