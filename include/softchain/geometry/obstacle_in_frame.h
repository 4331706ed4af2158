#pragma once
// ObstacleInFrame: a rigid obstacle's signed distance g as a function of the
// coordinates L of another frame -- a chain link's, whose points lie at
// x = c + R L in the world -- for a search that tests many points given in
// that frame. With the obstacle at `pose` (RigidTransform), a point's rest
// coordinates are affine in L,
//     y = to_rest(c + R L) = A L + b,   A = R_o^T R,   b = to_rest(c),
// and a plane, sphere or cylinder seen from the frame is the same shape with
// its point and direction mapped back, p_L = A^T (p - b), a_L = A^T a (A is
// a rotation, so distances are kept). Their g then costs a few flops per
// point: no transform, no virtual call. Other shapes (box, triangle surface)
// map the point, y = A L + b, and ask the obstacle.
#include <Eigen/Core>

namespace softchain::geometry
{
  class RigidObstacle;

  class ObstacleInFrame
  {
  public:
    enum class Kind
    {
      plane,    // g = (L - p) . a
      sphere,   // g = |L - p| - r
      cylinder, // g = |w| - r,  w = (L - p) - ((L - p) . a) a
      general   // g = obstacle's gap at A L + b
    };

    ObstacleInFrame() = default;
    // An analytic shape seen from the frame (p, a, r already in its coordinates).
    ObstacleInFrame(Kind kind, const Eigen::Vector3d &point, const Eigen::Vector3d &direction, double radius);
    // Any obstacle, through its rest coordinates y = A L + b.
    ObstacleInFrame(const RigidObstacle &obstacle, const Eigen::Matrix3d &A, const Eigen::Vector3d &b);

    bool is_plane() const { return kind_ == Kind::plane; }

    double gap(const Eigen::Vector3d &L) const
    {
      const Eigen::Vector3d d = L - point_;
      switch (kind_)
        {
          case Kind::plane:
            return d.dot(direction_);
          case Kind::sphere:
            return d.norm() - radius_;
          case Kind::cylinder:
            return (d - d.dot(direction_) * direction_).norm() - radius_;
          default:
            return general_gap(L);
        }
    }

    // Whether g(L) < `distance`; round shapes compare squares,
    // |w| - r < d  <=>  |w|^2 < (r + d)^2 where r + d > 0, never otherwise.
    bool closer_than(const Eigen::Vector3d &L, const double distance) const
    {
      const Eigen::Vector3d d     = L - point_;
      const double          reach = radius_ + distance;
      switch (kind_)
        {
          case Kind::plane:
            return d.dot(direction_) < distance;
          case Kind::sphere:
            return reach > 0.0 && d.squaredNorm() < reach * reach;
          case Kind::cylinder:
            return reach > 0.0 && (d - d.dot(direction_) * direction_).squaredNorm() < reach * reach;
          default:
            return general_gap(L) < distance;
        }
    }

    // g and the unit outward normal n in the frame's coordinates (R n in
    // the world): a / (L - p) / w over its length; on a sphere's centre or a
    // cylinder's axis, where n is undefined, any unit vector (normal to the axis).
    double gap_and_normal(const Eigen::Vector3d &L, Eigen::Vector3d &n) const;

    // g and n as above, and the curvature of g along e, e^T H e (H = grad
    // grad g: 0 on a plane, (|P e|^2 - (n . e)^2) / |w| about a sphere's
    // centre (P = I) or a cylinder's axis (P = I - a a^T)).
    double gap_normal_and_curvature(const Eigen::Vector3d &L, const Eigen::Vector3d &e, Eigen::Vector3d &n,
                                    double &curvature) const;

  private:
    double general_gap(const Eigen::Vector3d &L) const;

    Kind                 kind_ = Kind::general;
    Eigen::Vector3d      point_     = Eigen::Vector3d::Zero();
    Eigen::Vector3d      direction_ = Eigen::Vector3d::Zero();
    double               radius_    = 0.0;
    const RigidObstacle *obstacle_  = nullptr;
    Eigen::Matrix3d      A_         = Eigen::Matrix3d::Identity();
    Eigen::Vector3d      b_         = Eigen::Vector3d::Zero();
  };
} // namespace softchain::geometry
