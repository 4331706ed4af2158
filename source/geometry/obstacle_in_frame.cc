#include <softchain/geometry/obstacle_in_frame.h>
#include <softchain/geometry/rigid_obstacle.h>

#include <Eigen/Geometry>

namespace softchain::geometry
{
  ObstacleInFrame::ObstacleInFrame(const Kind kind, const Eigen::Vector3d &point, const Eigen::Vector3d &direction,
                                   const double radius)
    : kind_(kind)
    , point_(point)
    , direction_(direction)
    , radius_(radius)
  {}

  ObstacleInFrame::ObstacleInFrame(const RigidObstacle &obstacle, const Eigen::Matrix3d &A, const Eigen::Vector3d &b)
    : obstacle_(&obstacle)
    , A_(A)
    , b_(b)
  {}

  double ObstacleInFrame::gap_and_normal(const Eigen::Vector3d &L, Eigen::Vector3d &n) const
  {
    const Eigen::Vector3d d = L - point_;
    Eigen::Vector3d       w;
    switch (kind_)
      {
        case Kind::plane:
          n = direction_;
          return d.dot(direction_);
        case Kind::sphere:
          w = d;
          break;
        case Kind::cylinder:
          w = d - d.dot(direction_) * direction_;
          break;
        default:
          {
            const double gap = obstacle_->gap_and_normal_at_rest(A_ * L + b_, n);
            n                = A_.transpose() * n;
            return gap;
          }
      }
    const double r = w.norm();
    if (r == 0.0)
      n = kind_ == Kind::sphere ? Eigen::Vector3d::UnitX() : direction_.unitOrthogonal();
    else
      n = (1.0 / r) * w;
    return r - radius_;
  }

  double ObstacleInFrame::gap_normal_and_curvature(const Eigen::Vector3d &L, const Eigen::Vector3d &e,
                                                   Eigen::Vector3d &n, double &curvature) const
  {
    if (kind_ == Kind::general)
      {
        const SignedDistance d = obstacle_->distance_at_rest(A_ * L + b_);
        const Eigen::Vector3d  e_rest = A_ * e;
        n                             = A_.transpose() * d.normal;
        curvature                     = e_rest.dot(d.hessian * e_rest);
        return d.gap;
      }
    const double gap = gap_and_normal(L, n);
    curvature        = 0.0;
    if (kind_ != Kind::plane)
      {
        const double          r  = gap + radius_; // |w|
        const Eigen::Vector3d Pe = kind_ == Kind::sphere ? e : Eigen::Vector3d(e - e.dot(direction_) * direction_);
        if (r > 0.0)
          curvature = (Pe.squaredNorm() - n.dot(e) * n.dot(e)) / r;
      }
    return gap;
  }

  double ObstacleInFrame::general_gap(const Eigen::Vector3d &L) const { return obstacle_->gap_at_rest(A_ * L + b_); }
} // namespace softchain::geometry
