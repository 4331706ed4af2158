// ExternalForceTorque: only distal force points count, the lever arm is the
// deformed point minus the deformed joint centre, the result is in the joint
// frame. Tolerance 1e-15 N m: a few products of numbers of order 1.
#include <softchain/data/input_error.h>
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/external_force_torque.h>

#include <catch2/catch.hpp>

using namespace softchain;
using namespace softchain::reduction;

namespace
{
  data::SampleRecord loaded_sample()
  {
    data::SampleRecord s;
    s.id = "forces";
    // Reference points at x = 0.2 (proximal to a joint at 0.5) and 0.8.
    s.actuation.point_forces  = {{{0.2, 0, 0}, {0, 5, 0}}, {{0.8, 0, 0}, {0, 0, 2}}};
    s.force_points_deformed   = {{0.2, 0.1, 0}, {0.7, 0.3, -0.1}};
    return s;
  }
} // namespace

TEST_CASE("external force torque: distal forces, deformed lever arm, joint frame")
{
  const data::SampleRecord  sample = loaded_sample();
  const ExternalForceTorque torque(sample);
  const Eigen::Vector3d     J(0.5, 0.1, 0.0);
  const Eigen::Matrix3d     frame = data::rotation_from_angles({0.1, -0.2, 0.4});
  // Only the force at X = 0.8 is distal: (x - J) = (0.2, 0.2, -0.1), f = (0, 0, 2),
  // (x - J) x f = (0.2 * 2 - 0, -(0.2 * 2 - 0), 0) = (0.4, -0.4, 0).
  const Eigen::Vector3d want = frame.transpose() * Eigen::Vector3d(0.4, -0.4, 0);
  CHECK((torque.about(0.5, J, frame) - want).norm() < 1e-15);
  // Beyond both points nothing is distal.
  CHECK(torque.about(0.9, J, frame).norm() == 0);
}

TEST_CASE("external force torque: missing deformed force points name the sample")
{
  data::SampleRecord sample = loaded_sample();
  sample.force_points_deformed.pop_back();
  CHECK_THROWS_WITH(ExternalForceTorque(sample), Catch::Contains("sample 'forces'"));
}
