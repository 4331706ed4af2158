#pragma once
// RigidObstacle: a rigid body the finger may touch, described by the signed
// distance d of a point to its surface in its rest pose. Moved from it by a
// rigid transform x = R (y - p) + p + c (RigidTransform: a turn R about the
// pivot p, then a translation c), it has at x
//     g(x) = d(y),   n(x) = R grad d(y),   H(x) = R (grad grad d(y)) R^T,
//     y = R^T (x - p - c) + p,
// as the distance is invariant under rigid motions. g > 0 is the gap
// outside the obstacle, g < 0 the penetration inside it; n is the unit
// outward normal at the closest surface point and H the curvature of the
// level set (zero on flat parts). The FEM's contact (PenaltyContact) needs
// g and n for its residual and H for its consistent tangent. The shapes are
// analytic (Hart, "Sphere tracing", The Visual Computer 12, 1996, lists the
// distance functions); TriangulatedObstacle is a closed triangle mesh.
#include <softchain/geometry/obstacle_in_frame.h>
#include <softchain/geometry/rigid_transform.h>

#include <Eigen/Dense>

#include <string>

namespace softchain::geometry
{
  struct SignedDistance
  {
    double          gap;
    Eigen::Vector3d normal;
    Eigen::Matrix3d hessian;
  };

  class RigidObstacle
  {
  public:
    virtual ~RigidObstacle() = default;
    // At x, with the obstacle moved by `pose` from its rest pose.
    SignedDistance distance(const Eigen::Vector3d &x, const RigidTransform &pose = RigidTransform()) const;
    virtual SignedDistance distance_at_rest(const Eigen::Vector3d &x) const = 0;
    // g alone (no normal or curvature): what a search for the points inside
    // an obstacle needs for most of the points it tests.
    double gap(const Eigen::Vector3d &x, const RigidTransform &pose = RigidTransform()) const
    {
      return gap_at_rest(pose.to_rest(x));
    }
    virtual double gap_at_rest(const Eigen::Vector3d &x) const { return distance_at_rest(x).gap; }
    // g and n alone (no curvature): what a contact search's candidates need.
    double gap_and_normal(const Eigen::Vector3d &x, Eigen::Vector3d &normal,
                          const RigidTransform &pose = RigidTransform()) const;
    virtual double gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &normal) const
    {
      const SignedDistance d = distance_at_rest(x);
      normal                 = d.normal;
      return d.gap;
    }
    // Whether g(x) < `distance`, without g's square root where it has one
    // (round obstacles compare squares): the test a contact search makes of
    // every point near an obstacle.
    bool closer_than(const Eigen::Vector3d &x, const double distance, const RigidTransform &pose = RigidTransform()) const
    {
      return closer_than_at_rest(pose.to_rest(x), distance);
    }
    virtual bool closer_than_at_rest(const Eigen::Vector3d &x, const double distance) const
    {
      return gap_at_rest(x) < distance;
    }
    // The obstacle at `pose` seen from the frame whose points lie at
    // x = c + R L (ObstacleInFrame: A = R_o^T R, b = to_rest(c)).
    ObstacleInFrame seen_from(const Eigen::Matrix3d &R, const Eigen::Vector3d &c,
                              const RigidTransform &pose = RigidTransform()) const
    {
      return in_frame(pose.is_turned() ? Eigen::Matrix3d(pose.rotation().transpose() * R) : R, pose.to_rest(c));
    }
    // The same from the map y = A L + b to the rest coordinates: the shape
    // itself where it maps onto one, otherwise the general form.
    virtual ObstacleInFrame in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const
    {
      return ObstacleInFrame(*this, A, b);
    }
    // "plane", "sphere", "cylinder", "box" or "stl".
    virtual std::string shape() const = 0;
  };

  // The half-space below a plane: g = (x - p) . n, n the plane's unit normal
  // pointing out of the obstacle.
  class PlaneObstacle : public RigidObstacle
  {
  public:
    PlaneObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &normal);
    SignedDistance distance_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &normal) const override;
    ObstacleInFrame in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const override;
    std::string    shape() const override { return "plane"; }

  private:
    Eigen::Vector3d point, normal;
  };

  // g = |x - c| - R, n = (x - c) / |x - c|, H = (I - n n^T) / |x - c|.
  class SphereObstacle : public RigidObstacle
  {
  public:
    SphereObstacle(const Eigen::Vector3d &center, double radius);
    SignedDistance distance_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &normal) const override;
    bool           closer_than_at_rest(const Eigen::Vector3d &x, double distance) const override;
    ObstacleInFrame in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const override;
    std::string    shape() const override { return "sphere"; }

  private:
    Eigen::Vector3d center;
    double          radius;
  };

  // An infinite circular cylinder about the axis through `point` along the
  // unit `axis`: with w the part of x - point normal to the axis,
  // g = |w| - R, n = w / |w|, H = (I - a a^T - n n^T) / |w|.
  class CylinderObstacle : public RigidObstacle
  {
  public:
    CylinderObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &axis, double radius);
    SignedDistance distance_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_and_normal_at_rest(const Eigen::Vector3d &x, Eigen::Vector3d &normal) const override;
    bool           closer_than_at_rest(const Eigen::Vector3d &x, double distance) const override;
    ObstacleInFrame in_frame(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) const override;
    std::string    shape() const override { return "cylinder"; }

  private:
    Eigen::Vector3d point, axis;
    Eigen::Matrix3d normal_projection; // P = I - a a^T
    double          radius;
  };

  // A box with the given center and half sizes along its own axes, turned
  // from the world axes by the rotation R. In the box's frame, y = R^T (x - c):
  // outside, with q the closest point (y clamped to the box) and o_i = 1 for
  // the components clamped, g = |y - q|, n_b = (y - q) / g,
  // H_b = (diag(o) - n_b n_b^T) / g (flat against a face, a cylinder's about
  // an edge, a sphere's about a corner); inside, the nearest face's plane.
  // In world axes n = R n_b and H = R H_b R^T (g is invariant).
  class BoxObstacle : public RigidObstacle
  {
  public:
    BoxObstacle(const Eigen::Vector3d &center, const Eigen::Vector3d &half_sizes,
                const Eigen::Matrix3d &rotation = Eigen::Matrix3d::Identity());
    SignedDistance distance_at_rest(const Eigen::Vector3d &x) const override;
    double         gap_at_rest(const Eigen::Vector3d &x) const override;
    std::string    shape() const override { return "box"; }

  private:
    SignedDistance distance_in_box_frame(const Eigen::Vector3d &y) const;

    Eigen::Vector3d center, half_sizes;
    Eigen::Matrix3d rotation;
  };
} // namespace softchain::geometry
