// The joint torques the reduction writes are the generalised forces of the
// joint's Euler angles (SampleReduction::conjugate_torque): the virtual work
// of the moment on the distal link per unit change of each angle. Checked
// against that work computed by central differences of the rotation, with
// no use of the formula: a change dq_a of angle a turns the distal frame by
// w_a dq_a, w_a = vee(dR/dq_a R^T), and Q_a = M . w_a (the twist's moment
// about the twist point, the bending moments about the joint centre).
// Tolerance 1e-9 of |m|: the central difference's error is h^2 |R'''| / 6
// ~ 2e-11 at h = 1e-5, its round-off about 1e-16 / h = 1e-11.
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/sample_reduction.h>

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <cmath>

using namespace softchain;
using softchain::reduction::SampleReduction;

namespace
{
  // The proximal-frame angular velocity of the distal frame per unit change
  // of angle `axis` (0: psi, 1: theta, 2: phi) at q.
  Eigen::Vector3d turn_per_angle(const data::JointAngles &q, const int axis)
  {
    const double h     = 1e-5;
    auto         moved = [&](const double step) {
      data::JointAngles p = q;
      (axis == 0 ? p.psi : axis == 1 ? p.theta : p.phi) += step;
      return data::rotation_from_angles(p);
    };
    const Eigen::Matrix3d W = (moved(h) - moved(-h)) / (2 * h) * data::rotation_from_angles(q).transpose();
    return {W(2, 1), W(0, 2), W(1, 0)};
  }
} // namespace

TEST_CASE("joint torques are the Euler angles' generalised forces: the virtual work of the moments")
{
  // A straight joint, one bent in its plane as an inflated finger's joints
  // are, and one turned about all three axes.
  const data::JointAngles angles[] = {{0, 0, 0}, {0, 0, -0.21}, {0.3, -0.4, 0.7}};
  // The moments on the distal link in its own frame: about the twist point
  // and about the joint centre (they differ by the lever of the force).
  const Eigen::Vector3d about_twist(0.012, -0.034, 0.021), about_centre(0.015, -0.031, 0.019);
  for (const data::JointAngles &q : angles)
    {
      const Eigen::Matrix3d R = data::rotation_from_angles(q);
      const Eigen::Vector3d Q = SampleReduction::conjugate_torque(q, about_twist, about_centre);
      const Eigen::Vector3d want(turn_per_angle(q, 0).dot(R * about_twist),
                                 turn_per_angle(q, 1).dot(R * about_centre),
                                 turn_per_angle(q, 2).dot(R * about_centre));
      CHECK((Q - want).norm() < 1e-9 * about_centre.norm());
    }
  // The frame's own components are not those forces once the joint is bent:
  // at phi = -0.21 a lateral moment alone (m_y) does work on the twist,
  // Q_psi = -sin(phi) m_y, about a fifth of m_y.
  const Eigen::Vector3d lateral(0, 0.01, 0);
  const Eigen::Vector3d Q = SampleReduction::conjugate_torque({0, 0, -0.21}, lateral, lateral);
  CHECK(Q.x() == Approx(std::sin(0.21) * 0.01).epsilon(1e-12));
  CHECK(Q.y() == Approx(std::cos(0.21) * 0.01).epsilon(1e-12));
}
