// The Euler convention R = Rx(psi) Ry(theta) Rz(phi), checked against
// elementary rotation matrices written out here, and its inverse.
#include <softchain/data/joint_angles.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace softchain::data;

namespace
{
  Eigen::Matrix3d rx(double a)
  {
    Eigen::Matrix3d R;
    R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
    return R;
  }
  Eigen::Matrix3d ry(double a)
  {
    Eigen::Matrix3d R;
    R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
    return R;
  }
  Eigen::Matrix3d rz(double a)
  {
    Eigen::Matrix3d R;
    R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    return R;
  }
} // namespace

TEST_CASE("Euler angles: R = Rx(psi) Ry(theta) Rz(phi) and back")
{
  // A grid over psi, phi in (-pi, pi) and theta in (-pi/2, pi/2), away from
  // the singular theta = +-pi/2. Tolerance: a few ulps of pi, the round-off
  // of three matrix products and an atan2 (~1e-15).
  for (double psi = -3.0; psi <= 3.0; psi += 0.75)
    for (double theta = -1.5; theta <= 1.5; theta += 0.5)
      for (double phi = -3.0; phi <= 3.0; phi += 0.75)
        {
          const Eigen::Matrix3d R = rotation_from_angles({psi, theta, phi});
          CHECK((R - rx(psi) * ry(theta) * rz(phi)).norm() < 1e-14);
          const JointAngles back = angles_from_rotation(R);
          CHECK(back.psi == Approx(psi).margin(1e-13));
          CHECK(back.theta == Approx(theta).margin(1e-13));
          CHECK(back.phi == Approx(phi).margin(1e-13));
        }
}

TEST_CASE("Euler angles: a single-axis rotation gives one angle")
{
  const JointAngles bend = angles_from_rotation(rz(-0.3));
  CHECK(bend.phi == Approx(-0.3).margin(1e-15));
  CHECK(bend.psi == 0.0);
  CHECK(bend.theta == 0.0);
}
