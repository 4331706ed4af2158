#pragma once
// JointStiffness: the paper's diagonal joint stiffness (Sec. III-C)
//   tau_i = K_i q_i,  K_i = diag(k_psi,i, k_theta,i, k_phi,i),
// optionally with k_phi,i interpolated in pressure (the reduction's secant
// k_phi(p) = tau_phi(p) / phi(p), which decreases with pressure, Fig. 5).
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>
#include <vector>

namespace softchain::chain
{
  class JointStiffness
  {
  public:
    // One (k_psi, k_theta, k_phi) per joint, each positive and finite
    // (N m / rad); throws std::invalid_argument otherwise.
    explicit JointStiffness(std::vector<Eigen::Vector3d> per_joint);

    // Makes k_phi of joint i follow bending_in_pressure[i](p).
    void set_bending_in_pressure(std::vector<PiecewiseLinear> bending_in_pressure);

    int                    n_joints() const { return static_cast<int>(per_joint_.size()); }
    const Eigen::Vector3d &joint(int i) const { return per_joint_[i]; }
    bool depends_on_pressure() const { return !bending_in_pressure_.empty(); }

    // diag(K) = (k_psi,0, k_theta,0, k_phi,0, ...) at pressure p.
    Eigen::VectorXd diagonal(double pressure) const;

  private:
    std::vector<Eigen::Vector3d> per_joint_;
    std::vector<PiecewiseLinear> bending_in_pressure_;
  };
} // namespace softchain::chain
