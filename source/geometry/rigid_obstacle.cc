#include <softchain/geometry/rigid_obstacle.h>

#include <softchain/data/input_error.h>

#include <cmath>

namespace softchain::geometry
{
  namespace
  {
    Eigen::Vector3d unit(const Eigen::Vector3d &v, const std::string &what)
    {
      if (!(v.norm() > 0))
        throw data::InputError(what + " must be a nonzero vector");
      return v.normalized();
    }

    void check_positive(const double value, const std::string &what)
    {
      if (!(value > 0))
        throw data::InputError(what + " must be > 0");
    }

    // The distance's derivatives where it is |w| - R about a centre line or
    // point: n = w / |w| and H = (P - n n^T) / |w|, P the projection onto
    // the directions w may take. At |w| = 0 (on the axis or at the centre)
    // the normal is undefined; a fixed direction keeps g finite there.
    // The gap and normal of `radial` alone.
    double radial_gap(const Eigen::Vector3d &w, const double radius, const Eigen::Matrix3d &P, Eigen::Vector3d &n)
    {
      const double r = w.norm();
      n              = r == 0 ? Eigen::Vector3d(P.col(0).normalized()) : Eigen::Vector3d((1.0 / r) * w);
      return r - radius;
    }

    SignedDistance radial(const Eigen::Vector3d &w, const double radius, const Eigen::Matrix3d &P)
    {
      const double r = w.norm();
      if (r == 0)
        return {-radius, P.col(0).normalized(), Eigen::Matrix3d::Zero()};
      const double          inverse = 1.0 / r; // one division (a contact search calls this per point)
      const Eigen::Vector3d n       = inverse * w;
      return {r - radius, n, inverse * (P - n * n.transpose())};
    }
  } // namespace

  double RigidObstacle::gap_and_normal(const Eigen::Vector3d &x, Eigen::Vector3d &normal,
                                       const RigidTransform &pose) const
  {
    const double gap = gap_and_normal_at_rest(pose.to_rest(x), normal);
    if (pose.is_turned())
      normal = pose.rotation() * normal;
    return gap;
  }

  SignedDistance RigidObstacle::distance(const Eigen::Vector3d &x, const RigidTransform &pose) const
  {
    const SignedDistance rest = distance_at_rest(pose.to_rest(x));
    if (!pose.is_turned())
      return rest;
    const Eigen::Matrix3d &R = pose.rotation();
    return {rest.gap, R * rest.normal, R * rest.hessian * R.transpose()};
  }

  PlaneObstacle::PlaneObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &normal)
    : point(point)
    , normal(unit(normal, "a plane's normal"))
  {}

  SignedDistance PlaneObstacle::distance_at_rest(const Eigen::Vector3d &x) const
  {
    return {(x - point).dot(normal), normal, Eigen::Matrix3d::Zero()};
  }

  double PlaneObstacle::gap_at_rest(const Eigen::Vector3d &x) const { return (x - point).dot(normal); }

  double PlaneObstacle::gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &n) const
  {
    n = normal;
    return gap_at_rest(x);
  }

  // (y - point) . n with y = A L + b: (L - A^T (point - b)) . A^T n.
  ObstacleInFrame PlaneObstacle::in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const
  {
    return {ObstacleInFrame::Kind::plane, A.transpose() * (point - b), A.transpose() * normal, 0.0};
  }

  SphereObstacle::SphereObstacle(const Eigen::Vector3d &center, const double radius)
    : center(center)
    , radius(radius)
  {
    check_positive(radius, "a sphere's radius");
  }

  SignedDistance SphereObstacle::distance_at_rest(const Eigen::Vector3d &x) const
  {
    return radial(x - center, radius, Eigen::Matrix3d::Identity());
  }

  double SphereObstacle::gap_at_rest(const Eigen::Vector3d &x) const { return (x - center).norm() - radius; }

  double SphereObstacle::gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &n) const
  {
    return radial_gap(x - center, radius, Eigen::Matrix3d::Identity(), n);
  }

  // |x - c| - R < d  <=>  |x - c|^2 < (R + d)^2 where R + d > 0, never otherwise.
  bool SphereObstacle::closer_than_at_rest(const Eigen::Vector3d &x, const double distance) const
  {
    const double reach = radius + distance;
    return reach > 0.0 && (x - center).squaredNorm() < reach * reach;
  }

  ObstacleInFrame SphereObstacle::in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const
  {
    return {ObstacleInFrame::Kind::sphere, A.transpose() * (center - b), Eigen::Vector3d::Zero(), radius};
  }

  CylinderObstacle::CylinderObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &axis,
                                     const double radius)
    : point(point)
    , axis(unit(axis, "a cylinder's axis"))
    , normal_projection(Eigen::Matrix3d::Identity() - this->axis * this->axis.transpose())
    , radius(radius)
  {
    check_positive(radius, "a cylinder's radius");
  }

  SignedDistance CylinderObstacle::distance_at_rest(const Eigen::Vector3d &x) const
  {
    return radial(normal_projection * (x - point), radius, normal_projection);
  }

  double CylinderObstacle::gap_at_rest(const Eigen::Vector3d &x) const
  {
    const Eigen::Vector3d d = x - point;
    return (d - d.dot(axis) * axis).norm() - radius;
  }

  double CylinderObstacle::gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &n) const
  {
    return radial_gap(normal_projection * (x - point), radius, normal_projection, n);
  }

  // |w| - R < d  <=>  |w|^2 < (R + d)^2 where R + d > 0, never otherwise.
  bool CylinderObstacle::closer_than_at_rest(const Eigen::Vector3d &x, const double distance) const
  {
    const double          reach = radius + distance;
    const Eigen::Vector3d d     = x - point;
    return reach > 0.0 && (d - d.dot(axis) * axis).squaredNorm() < reach * reach;
  }

  ObstacleInFrame CylinderObstacle::in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const
  {
    return {ObstacleInFrame::Kind::cylinder, A.transpose() * (point - b), A.transpose() * axis, radius};
  }

  BoxObstacle::BoxObstacle(const Eigen::Vector3d &center, const Eigen::Vector3d &half_sizes,
                           const Eigen::Matrix3d &rotation)
    : center(center)
    , half_sizes(half_sizes)
    , rotation(rotation)
  {
    for (int i = 0; i < 3; ++i)
      check_positive(half_sizes[i], "a box's half sizes");
  }

  SignedDistance BoxObstacle::distance_at_rest(const Eigen::Vector3d &x) const
  {
    const SignedDistance b = distance_in_box_frame(rotation.transpose() * (x - center));
    return {b.gap, rotation * b.normal, rotation * b.hessian * rotation.transpose()};
  }

  // Outside: the distance to the clamped point; inside: minus the depth
  // below the nearest face.
  double BoxObstacle::gap_at_rest(const Eigen::Vector3d &x) const
  {
    const Eigen::Vector3d y = rotation.transpose() * (x - center);
    const Eigen::Vector3d d = y - y.cwiseMax(-half_sizes).cwiseMin(half_sizes);
    if (d.norm() > 0)
      return d.norm();
    return -(half_sizes - y.cwiseAbs()).minCoeff();
  }

  SignedDistance BoxObstacle::distance_in_box_frame(const Eigen::Vector3d &y) const
  {
    const Eigen::Vector3d q = y.cwiseMax(-half_sizes).cwiseMin(half_sizes);
    const Eigen::Vector3d d = y - q;
    if (d.norm() > 0)
      {
        Eigen::Matrix3d clamped = Eigen::Matrix3d::Zero();
        for (int i = 0; i < 3; ++i)
          if (d[i] != 0)
            clamped(i, i) = 1;
        return radial(d, 0.0, clamped);
      }
    // Inside: the face the point is closest to.
    int    k     = 0;
    double depth = half_sizes[0] - std::abs(y[0]);
    for (int i = 1; i < 3; ++i)
      if (half_sizes[i] - std::abs(y[i]) < depth)
        {
          k     = i;
          depth = half_sizes[i] - std::abs(y[i]);
        }
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    n[k]              = y[k] < 0 ? -1 : 1;
    return {-depth, n, Eigen::Matrix3d::Zero()};
  }
} // namespace softchain::geometry
