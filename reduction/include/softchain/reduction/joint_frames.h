#pragma once
// JointFrames: the deformed frame F_i of every joint of one sample by one
// method, and the relative rotations between neighbours,
//   R_i = R_{i-1}^T R_i^0   (R_0 = identity, docs/conventions.md "Joints"),
// read as angles with data::angles_from_rotation (R = Rx(psi) Ry(theta) Rz(phi)).
// The deformed joint centre is the image of the reference centre under the
// slab's affine fit, J_i = A_i J_i,0 + u_i, for both methods, so that M1 and
// M2 differ only in the rotation.
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/slab_selection.h>

#include <Eigen/Core>

namespace softchain::reduction
{
  struct JointFrame
  {
    Eigen::Matrix3d rotation;  // R_i^0: the joint's axes in world coordinates
    Eigen::Vector3d centre;    // J_i, deformed
    Eigen::Vector3d stretches; // principal stretches of U_i (M2); NaN for M1
  };

  class JointFrames
  {
  public:
    JointFrames(RotationMethod method, const std::vector<SlabSelection> &slabs,
                const std::vector<data::Point3> &X, const std::vector<data::Point3> &x,
                const std::string &sample);

    // Frame of the joint with 0-based index i.
    const JointFrame &operator[](std::size_t i) const { return frames_[i]; }
    std::size_t       size() const { return frames_.size(); }
    // Angles of R_i = R_{i-1}^T R_i^0 for the joint with 0-based index i.
    data::JointAngles relative_angles(std::size_t i) const;

  private:
    std::vector<JointFrame> frames_;
  };
} // namespace softchain::reduction
