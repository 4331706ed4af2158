// R = Rx(psi) Ry(theta) Rz(phi) and its inverse (joint_angles.h). Multiplying
// out the three elementary rotations gives
//   R(0,2) =  sin(theta)
//   R(1,2) = -sin(psi) cos(theta),   R(2,2) = cos(psi) cos(theta)
//   R(0,1) = -cos(theta) sin(phi),   R(0,0) = cos(theta) cos(phi)
// from which the angles follow with atan2 (cos(theta) > 0 on (-pi/2, pi/2)).
#include <softchain/data/joint_angles.h>

#include <Eigen/Geometry>

#include <cmath>

namespace softchain::data
{
  Eigen::Matrix3d rotation_from_angles(const JointAngles &angles)
  {
    const Eigen::AngleAxisd rx(angles.psi, Eigen::Vector3d::UnitX());
    const Eigen::AngleAxisd ry(angles.theta, Eigen::Vector3d::UnitY());
    const Eigen::AngleAxisd rz(angles.phi, Eigen::Vector3d::UnitZ());
    return (rx * ry * rz).toRotationMatrix();
  }

  JointAngles angles_from_rotation(const Eigen::Matrix3d &R)
  {
    JointAngles angles;
    angles.theta = std::atan2(R(0, 2), std::hypot(R(0, 0), R(0, 1)));
    angles.psi   = std::atan2(-R(1, 2), R(2, 2));
    angles.phi   = std::atan2(-R(0, 1), R(0, 0));
    return angles;
  }
} // namespace softchain::data
