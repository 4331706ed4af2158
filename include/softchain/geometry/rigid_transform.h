#pragma once
// RigidTransform: the pose of a rigid obstacle away from its rest pose, a
// turn R about a pivot p followed by a translation c:
//     x = R (y - p) + p + c          (y at rest, x in the world),
//     y = R^T (x - p - c) + p.
// Along a load path with parameter t in [0, 1] an obstacle with Motion c and
// Motion rotation w (a rotation vector, rad) takes the pose
//     R(t) = exp(t [w]x),  translation t c,
// exp of the skew matrix [w]x being the turn about w / |w| by t |w|
// (Rodrigues' formula).
#include <Eigen/Dense>

namespace softchain::geometry
{
  class RigidTransform
  {
  public:
    RigidTransform() = default;
    RigidTransform(const Eigen::Matrix3d &rotation, const Eigen::Vector3d &pivot,
                   const Eigen::Vector3d &translation);
    // The pose at path parameter t: exp(t [w]x) about `pivot`, then t c.
    static RigidTransform along_path(double t, const Eigen::Vector3d &rotation_vector,
                                     const Eigen::Vector3d &pivot, const Eigen::Vector3d &translation);
    // The rotation matrix of the rotation vector v: about v / |v| by |v| rad.
    static Eigen::Matrix3d rotation_of(const Eigen::Vector3d &v);

    // Inline, and without the product by R where it is the identity (an
    // obstacle that only translates): a contact search calls it for every
    // surface point it tests.
    Eigen::Vector3d to_rest(const Eigen::Vector3d &x) const
    {
      const Eigen::Vector3d local = x - pivot - shift;
      return (turned ? Eigen::Vector3d(turn.transpose() * local) : local) + pivot;
    }
    Eigen::Vector3d to_world(const Eigen::Vector3d &y) const;
    const Eigen::Matrix3d &rotation() const { return turn; }
    // Whether R is not the identity.
    bool is_turned() const { return turned; }

  private:
    bool            turned = false;
    Eigen::Matrix3d turn  = Eigen::Matrix3d::Identity();
    Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  };
} // namespace softchain::geometry
