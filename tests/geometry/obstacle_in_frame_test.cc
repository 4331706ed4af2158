// An obstacle seen from another frame (ObstacleInFrame) against the same
// obstacle asked in the world: a point L of a frame at (c, R) lies at
// x = c + R L, so its gap, closer-than test, normal (R n) and curvature
// along a direction e (the world's Hessian applied to R e) must be the
// world's, for every shape (plane, sphere, cylinder, and the box through
// the general form), with the obstacle at rest and turned and moved.
#include <softchain/geometry/obstacle_in_frame.h>
#include <softchain/geometry/rigid_obstacle.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <vector>

using namespace softchain::geometry;
using Eigen::Vector3d;

TEST_CASE("an obstacle seen from a link's frame has the world's gap, normal and curvature", "[geometry][contact]")
{
  const Eigen::Matrix3d  turn = Eigen::AngleAxisd(0.7, Vector3d(0, 0.6, 0.8)).toRotationMatrix();
  const PlaneObstacle    plane(Vector3d(0.1, 0.2, 0.3), Vector3d(1, 2, 2));
  const SphereObstacle   sphere(Vector3d(0.1, 0.2, 0.3), 0.4);
  const CylinderObstacle cylinder(Vector3d(0.1, 0.2, 0.3), Vector3d(0, 1, 1), 0.4);
  const BoxObstacle      box(Vector3d(0.1, 0.2, 0.3), Vector3d(0.3, 0.2, 0.5), turn);
  const Eigen::Matrix3d  R = Eigen::AngleAxisd(-1.1, Vector3d(0.3, -0.2, 0.9).normalized()).toRotationMatrix();
  const Vector3d         c(0.05, -0.3, 0.2);
  const Vector3d         e = Vector3d(0.2, 1.0, -0.4).normalized();
  for (const RigidTransform &pose : {RigidTransform(), RigidTransform(turn, Vector3d(0.1, 0, 0), Vector3d(0.01, 0.02, 0.03))})
    for (const RigidObstacle *o : std::vector<const RigidObstacle *>{&plane, &sphere, &cylinder, &box})
      {
        const ObstacleInFrame seen = o->seen_from(R, c, pose);
        for (const Vector3d &L : {Vector3d(0.1, 0.25, 0.3), Vector3d(0.9, -0.4, 0.2), Vector3d(0.2, 0.2, 0.9),
                                  Vector3d(-0.5, 0.7, -0.6), Vector3d(0.15, 0.1, 0.35)})
          {
            const Vector3d       x     = c + R * L;
            const SignedDistance world = o->distance(x, pose);
            // One rotation and one translation of round-off: 1e-15 of the
            // unit lengths here, a few ulps.
            CHECK(seen.gap(L) == Approx(world.gap).margin(1e-14));
            Vector3d n;
            CHECK(seen.gap_and_normal(L, n) == Approx(world.gap).margin(1e-14));
            CHECK((R * n - world.normal).norm() < 1e-14);
            double curvature = 0.0;
            CHECK(seen.gap_normal_and_curvature(L, e, n, curvature) == Approx(world.gap).margin(1e-14));
            CHECK((R * n - world.normal).norm() < 1e-14);
            const Vector3d e_world = R * e;
            CHECK(curvature == Approx(e_world.dot(world.hessian * e_world)).margin(1e-12));
            for (const double d : {world.gap - 0.05, world.gap + 0.05, -1.0, 0.0, 0.3})
              CHECK(seen.closer_than(L, d) == (world.gap < d));
          }
      }
}
