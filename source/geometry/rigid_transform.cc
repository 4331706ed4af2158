#include <softchain/geometry/rigid_transform.h>

namespace softchain::geometry
{
  RigidTransform::RigidTransform(const Eigen::Matrix3d &rotation, const Eigen::Vector3d &pivot,
                                 const Eigen::Vector3d &translation)
    : turned(rotation != Eigen::Matrix3d::Identity())
    , turn(rotation)
    , pivot(pivot)
    , shift(translation)
  {}

  RigidTransform RigidTransform::along_path(const double t, const Eigen::Vector3d &rotation_vector,
                                            const Eigen::Vector3d &pivot, const Eigen::Vector3d &translation)
  {
    return RigidTransform(rotation_of(t * rotation_vector), pivot, t * translation);
  }

  Eigen::Matrix3d RigidTransform::rotation_of(const Eigen::Vector3d &v)
  {
    const double angle = v.norm();
    return angle > 0 ? Eigen::AngleAxisd(angle, v / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  }

  Eigen::Vector3d RigidTransform::to_world(const Eigen::Vector3d &y) const
  {
    return turn * (y - pivot) + pivot + shift;
  }
} // namespace softchain::geometry
