#pragma once
// StiffnessExtraction: the diagonal joint stiffness K_i = diag(k_psi, k_theta,
// k_phi) from tau_i = K_i (psi_i, theta_i, phi_i)^T (paper Sec. III-C), each
// axis from the samples whose role feeds it (paper Sec. IV-A: pressure-only
// samples for k_phi, lateral-force samples for k_theta, torsion samples for
// k_psi). Per sample k = tau / angle; a rotation with |angle| below the
// threshold gives no value (NaN, counted), never a huge or infinite one.
// Per joint and axis:
//   at the largest load: k of the usable sample with the largest load (the
//                        paper's choice), loads ordered by pressure first,
//                        then by force_norm;
//   fit:                 least squares over the usable samples,
//                        k = sum(tau angle) / sum(angle^2).
// A joint that no pressure sample loads (no usable k_phi) takes its k_phi
// from the in-plane tip force samples (ForceIncrementStiffness), if any.
// Per pressure, k_psi(p), k_theta(p) and the bending samples' k_phi(p) are
// fitted to force increments over the pressure-only state
// (force_increments()).
#include <softchain/reduction/force_increment_stiffness.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/sample_reduction.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace softchain::reduction
{
  // Axis index: 0 = psi (x, torsion), 1 = theta (y, lateral), 2 = phi (z).
  double angle_about(const data::JointAngles &angles, int axis);

  struct JointStiffness
  {
    Eigen::Vector3d    at_largest_load; // N m / rad, NaN when no usable sample
    Eigen::Vector3d    fit;             // N m / rad, NaN when no usable sample
    std::array<int, 3> n_used{{0, 0, 0}};
  };

  class StiffnessExtraction
  {
  public:
    StiffnessExtraction(const std::vector<SampleReduction> &samples,
                        const ReductionParameters &parameters, std::size_t n_joints);

    const std::vector<JointStiffness> &joints() const { return joints_; }
    // Stiffness about `axis` from the force samples' increments over the
    // pressure-only state: torsion samples for psi, lateral for theta, the
    // in-plane (bending) tip force samples for phi.
    const ForceIncrementStiffness &force_increments(int axis) const
    {
      return force_increments_[axis];
    }
    // Does joint i take its k_phi from the bending samples?
    bool phi_from_bending(std::size_t joint) const { return phi_from_bending_[joint]; }
    // Number of (sample, joint, axis) rotations below the threshold.
    int n_below_threshold() const { return n_below_threshold_; }
    // tau / angle of one sample, NaN below the threshold.
    double single(const SampleReduction &sample, std::size_t joint, int axis) const;
    // Does this sample's role feed the axis?
    bool feeds(const SampleReduction &sample, int axis) const;
  private:
    // Least squares k = sum(tau angle) / sum(angle^2) over those of
    // `samples` that give a single() value; NaN when none does.
    double fit_over(const std::vector<const SampleReduction *> &samples, std::size_t joint,
                    int axis) const;
    JointStiffness extract_joint(const std::vector<SampleReduction> &samples, std::size_t joint);
    void           extract_axis(const std::vector<SampleReduction> &samples, std::size_t joint,
                                int axis, JointStiffness &stiffness);

    std::array<std::vector<std::string>, 3> roles_;
    double                                  threshold_;
    std::vector<ForceIncrementStiffness>    force_increments_; // psi, theta, phi
    std::vector<bool>                       phi_from_bending_;
    std::vector<JointStiffness>             joints_;
    int                                     n_below_threshold_ = 0;
  };
} // namespace softchain::reduction
