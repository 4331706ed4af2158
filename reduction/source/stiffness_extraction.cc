// StiffnessExtraction: k = tau / angle per sample (paper Sec. III-C,
// k_j = tau_j / phi_j), the value at the largest load and the least-squares
// fit k = sum(tau angle) / sum(angle^2) per joint and axis.
#include <softchain/reduction/stiffness_extraction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace softchain::reduction
{
  namespace
  {
    constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

    // Loads compare by pressure first, then by the force magnitudes: the
    // k_phi samples are pressure-only, the others force-only.
    bool lighter(const SampleReduction &a, const SampleReduction &b)
    {
      if (std::abs(a.pressure()) != std::abs(b.pressure()))
        return std::abs(a.pressure()) < std::abs(b.pressure());
      return a.force_norm() < b.force_norm();
    }
  } // namespace

  double angle_about(const data::JointAngles &angles, int axis)
  {
    return axis == 0 ? angles.psi : axis == 1 ? angles.theta : angles.phi;
  }

  StiffnessExtraction::StiffnessExtraction(const std::vector<SampleReduction> &samples,
                                           const ReductionParameters          &parameters,
                                           std::size_t                         n_joints)
    : roles_{{parameters.torsion_roles, parameters.lateral_roles, parameters.pressure_roles}}
    , threshold_(parameters.rotation_threshold)
    , phi_from_bending_(n_joints, false)
  {
    const std::array<const std::vector<std::string> *, 3> force_roles{
      {&parameters.torsion_roles, &parameters.lateral_roles, &parameters.bending_roles}};
    for (int axis = 0; axis < 3; ++axis)
      force_increments_.emplace_back(samples, *force_roles[axis], parameters.pressure_roles, axis,
                                     parameters.rotation_threshold,
                                     parameters.force_samples_per_fit);
    for (std::size_t joint = 0; joint < n_joints; ++joint)
      joints_.push_back(extract_joint(samples, joint));
  }

  bool StiffnessExtraction::feeds(const SampleReduction &sample, int axis) const
  {
    const auto &roles = roles_[axis];
    return std::find(roles.begin(), roles.end(), sample.role()) != roles.end();
  }

  double StiffnessExtraction::single(const SampleReduction &sample, std::size_t joint,
                                     int axis) const
  {
    const JointResult &result = sample.joints()[joint];
    const double       angle  = angle_about(result.angles, axis);
    if (!(std::abs(angle) >= threshold_) || angle == 0)
      return no_value;
    // A joint that transmits no torque has no measurable stiffness: e.g. a
    // section through the solid base fill, distal to which lies the whole
    // closed cavity, whose pressure has no net moment. "No torque" is below
    // 1e-6 of the sample's largest joint torque (the geometric torques are
    // exact up to round-off, 1e-12 relative).
    double largest = 0;
    for (const JointResult &other : sample.joints())
      largest = std::max(largest, std::abs(other.torque(axis)));
    if (!(std::abs(result.torque(axis)) > 1e-6 * largest))
      return no_value;
    return result.torque(axis) / angle;
  }

  JointStiffness StiffnessExtraction::extract_joint(const std::vector<SampleReduction> &samples,
                                                    std::size_t                         joint)
  {
    JointStiffness stiffness;
    for (int axis = 0; axis < 3; ++axis)
      extract_axis(samples, joint, axis, stiffness);
    return stiffness;
  }

  void StiffnessExtraction::extract_axis(const std::vector<SampleReduction> &samples,
                                         std::size_t joint, int axis, JointStiffness &stiffness)
  {
    std::vector<const SampleReduction *> usable;
    const SampleReduction               *largest = nullptr;
    for (const auto &sample : samples)
      {
        if (!feeds(sample, axis))
          continue;
        if (std::isnan(single(sample, joint, axis)))
          {
            ++n_below_threshold_;
            continue;
          }
        usable.push_back(&sample);
        if (!largest || lighter(*largest, sample))
          largest = &sample;
      }
    stiffness.n_used[axis]          = static_cast<int>(usable.size());
    stiffness.at_largest_load(axis) = largest ? single(*largest, joint, axis) : no_value;
    stiffness.fit(axis)             = fit_over(usable, joint, axis);
    const ForceIncrementStiffness &bending = force_increments_[2];
    if (axis == 2 && usable.empty() && bending.n_used(joint) > 0)
      {
        phi_from_bending_[joint]        = true;
        stiffness.n_used[axis]          = bending.n_used(joint);
        stiffness.at_largest_load(axis) = bending.at_largest_load(joint);
        stiffness.fit(axis)             = bending.fit(joint);
      }
  }

  double StiffnessExtraction::fit_over(const std::vector<const SampleReduction *> &samples,
                                       std::size_t joint, int axis) const
  {
    double sum_tau_angle = 0, sum_angle_squared = 0;
    for (const SampleReduction *sample : samples)
      {
        if (std::isnan(single(*sample, joint, axis)))
          continue;
        const JointResult &result = sample->joints()[joint];
        const double       angle  = angle_about(result.angles, axis);
        sum_tau_angle += result.torque(axis) * angle;
        sum_angle_squared += angle * angle;
      }
    return sum_angle_squared > 0 ? sum_tau_angle / sum_angle_squared : no_value;
  }
} // namespace softchain::reduction
