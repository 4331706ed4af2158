#pragma once
// The one Euler convention of SoftChain (docs/conventions.md, "Euler angles"), shared by
// the reduction and the chain tiers:
//   R = Rx(psi) * Ry(theta) * Rz(phi)
// psi: torsion about x, theta: lateral bending about y, phi: principal bending
// about z (intrinsic x-y'-z'' angles). Singular only at theta = +-90 deg, a
// lateral bend that no single joint of a finger reaches.
#include <Eigen/Core>

namespace softchain::data
{
  struct JointAngles
  {
    double psi   = 0.0; // about x
    double theta = 0.0; // about y
    double phi   = 0.0; // about z
  };

  Eigen::Matrix3d rotation_from_angles(const JointAngles &angles);
  // Inverse of rotation_from_angles for theta in (-pi/2, pi/2).
  JointAngles angles_from_rotation(const Eigen::Matrix3d &R);
} // namespace softchain::data
