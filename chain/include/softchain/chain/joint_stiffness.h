#pragma once
// JointStiffness: the paper's diagonal joint stiffness (Sec. III-C)
//   tau_i = K_i q_i,  K_i = diag(k_psi,i, k_theta,i, k_phi,i),
// optionally with any axis interpolated in pressure: k_phi(p), the
// reduction's secant tau_phi(p) / phi(p) of the pressure samples (Fig. 5),
// and k_theta(p), k_psi(p) from lateral and torsion samples at several
// pressures (an inflated finger is stiffer sideways).
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>
#include <array>
#include <vector>

namespace softchain::chain
{
  class JointStiffness
  {
  public:
    // One (k_psi, k_theta, k_phi) per joint, each positive and finite
    // (N m / rad); throws std::invalid_argument otherwise.
    explicit JointStiffness(std::vector<Eigen::Vector3d> per_joint);

    // Makes k of joint i about `axis` (0 psi, 1 theta, 2 phi) follow
    // tables[i](p).
    void set_in_pressure(int axis, std::vector<PiecewiseLinear> tables);

    int                    n_joints() const { return static_cast<int>(per_joint_.size()); }
    const Eigen::Vector3d &joint(int i) const { return per_joint_[i]; }
    bool depends_on_pressure() const;
    // The tabulated pressures of every k(p) table (sorted, unique; empty if
    // K is constant): K(p) is linear between consecutive ones.
    std::vector<double> table_pressures() const;
    // The same of one axis' tables.
    std::vector<double> table_pressures(int axis) const;

    // diag(K) = (k_psi,0, k_theta,0, k_phi,0, ...) at pressure p.
    Eigen::VectorXd diagonal(double pressure) const;
    // The same into k (sized 3n; no allocation).
    void            diagonal(double pressure, Eigen::VectorXd &k) const;

  private:
    std::vector<Eigen::Vector3d> per_joint_;
    std::array<std::vector<PiecewiseLinear>, 3> in_pressure_;
  };
} // namespace softchain::chain
