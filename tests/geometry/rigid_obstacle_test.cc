// The obstacles' signed distances against what can be checked without
// them: known distances of chosen points, the normal as the distance's
// gradient and the Hessian as the normal's gradient, both by central
// differences, on every branch of every shape (outside and inside; a box's
// face, edge and corner regions).
#include <softchain/data/input_error.h>
#include <softchain/geometry/rigid_obstacle.h>

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

using namespace softchain::geometry;
using Eigen::Vector3d;

namespace
{
  // Central differences with step h: the error is O(h^2 |d^3 g|); for the
  // radii and distances here (>= 0.1) and h = 1e-6 it is below 1e-9, and
  // the round-off 1e-16 / h = 1e-10: a tolerance of 1e-6 leaves room.
  void check_derivatives(const RigidObstacle &o, const Vector3d &x)
  {
    const double         h = 1e-6;
    const SignedDistance d = o.distance_at_rest(x);
    for (int j = 0; j < 3; ++j)
      {
        Vector3d e = Vector3d::Zero();
        e[j]       = h;
        const SignedDistance plus = o.distance_at_rest(x + e), minus = o.distance_at_rest(x - e);
        CHECK((plus.gap - minus.gap) / (2 * h) == Approx(d.normal[j]).margin(1e-6));
        for (int i = 0; i < 3; ++i)
          CHECK((plus.normal[i] - minus.normal[i]) / (2 * h) == Approx(d.hessian(i, j)).margin(1e-6));
      }
    CHECK(d.normal.norm() == Approx(1.0).epsilon(1e-14));
  }
} // namespace

TEST_CASE("a plane's distance is the height above it", "[geometry][contact]")
{
  const PlaneObstacle plane(Vector3d(0, -1, 0), Vector3d(0, 2, 0));
  CHECK(plane.distance_at_rest(Vector3d(3, 0.5, -2)).gap == Approx(1.5));
  CHECK(plane.distance_at_rest(Vector3d(3, -1.25, -2)).gap == Approx(-0.25));
  check_derivatives(plane, Vector3d(0.3, 0.2, 0.1));
}

TEST_CASE("a sphere's and a cylinder's distances and curvatures", "[geometry][contact]")
{
  const SphereObstacle sphere(Vector3d(1, 2, 3), 0.5);
  CHECK(sphere.distance_at_rest(Vector3d(1, 2, 4)).gap == Approx(0.5));
  CHECK(sphere.distance_at_rest(Vector3d(1, 2.2, 3)).gap == Approx(-0.3));
  check_derivatives(sphere, Vector3d(1.3, 2.4, 3.5));  // outside
  check_derivatives(sphere, Vector3d(1.1, 2.2, 2.9));  // inside

  const CylinderObstacle cylinder(Vector3d(0, 0, 0), Vector3d(0, 0, 3), 1.0);
  CHECK(cylinder.distance_at_rest(Vector3d(3, 4, 17)).gap == Approx(4.0));
  CHECK(cylinder.distance_at_rest(Vector3d(0, 0.25, -5)).gap == Approx(-0.75));
  check_derivatives(cylinder, Vector3d(1.2, 0.7, 0.4));
  check_derivatives(cylinder, Vector3d(0.2, -0.3, 9.0));
  // The curvature along the axis is zero, across it 1/r.
  const SignedDistance d = cylinder.distance_at_rest(Vector3d(2, 0, 0));
  CHECK(d.hessian(2, 2) == Approx(0.0).margin(1e-15));
  CHECK(d.hessian(1, 1) == Approx(0.5));
}

TEST_CASE("a box's distance on its face, edge and corner regions and inside", "[geometry][contact]")
{
  const BoxObstacle box(Vector3d(0, 0, 0), Vector3d(1, 2, 3));
  CHECK(box.distance_at_rest(Vector3d(0.5, 2.5, 0)).gap == Approx(0.5));                 // face
  CHECK(box.distance_at_rest(Vector3d(4, 6, 0)).gap == Approx(5.0));                     // edge
  CHECK(box.distance_at_rest(Vector3d(2, 4, 5)).gap == Approx(3.0));                     // corner
  CHECK(box.distance_at_rest(Vector3d(0.2, 1.5, 0)).gap == Approx(-0.5));                // inside
  for (const Vector3d &x : {Vector3d(0.3, 2.4, -1.0), Vector3d(1.5, 2.7, 0.2), Vector3d(1.4, -2.3, 3.5),
                            Vector3d(0.1, 1.7, 0.2)})
    check_derivatives(box, x);
}

TEST_CASE("a turned box is the unturned box seen in its own axes", "[geometry][contact]")
{
  // A box turned by 0.5 rad about (1, 2, 2)/3: the gap at c + R y equals the
  // unturned box's at c + y, its normal and curvature turn with R.
  const Vector3d                  c(0.1, -0.2, 0.3), h(1, 2, 3);
  const Eigen::Matrix3d           R = Eigen::AngleAxisd(0.5, Vector3d(1, 2, 2) / 3).toRotationMatrix();
  const BoxObstacle               turned(c, h, R), straight(c, h);
  for (const Vector3d &y : {Vector3d(0.5, 2.5, 0), Vector3d(4, 6, 0), Vector3d(2, 4, 5), Vector3d(0.2, 1.5, 0)})
    {
      const SignedDistance a = turned.distance_at_rest(c + R * y), b = straight.distance_at_rest(c + y);
      CHECK(a.gap == Approx(b.gap).margin(1e-14));
      CHECK((a.normal - R * b.normal).norm() < 1e-14);
      CHECK((a.hessian - R * b.hessian * R.transpose()).norm() < 1e-14);
    }
  for (const Vector3d &y : {Vector3d(0.3, 2.4, -1.0), Vector3d(1.5, 2.7, 0.2), Vector3d(1.4, -2.3, 3.5),
                            Vector3d(0.1, 1.7, 0.2)})
    check_derivatives(turned, c + R * y);
}

TEST_CASE("the gap alone, and the gap with the normal, are the signed distance's, outside and inside every shape",
          "[geometry][contact]")
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(0, 0.6, 0.8)).toRotationMatrix();
  const PlaneObstacle    plane(Vector3d(0.1, 0.2, 0.3), Vector3d(1, 2, 2));
  const SphereObstacle   sphere(Vector3d(0.1, 0.2, 0.3), 0.4);
  const CylinderObstacle cylinder(Vector3d(0.1, 0.2, 0.3), Vector3d(0, 1, 1), 0.4);
  const BoxObstacle      box(Vector3d(0.1, 0.2, 0.3), Vector3d(0.3, 0.2, 0.5), R);
  for (const RigidObstacle *o : std::vector<const RigidObstacle *>{&plane, &sphere, &cylinder, &box})
    for (const Vector3d &x : {Vector3d(0.1, 0.25, 0.3), Vector3d(0.9, -0.4, 0.2), Vector3d(0.2, 0.2, 0.9),
                              Vector3d(-0.5, 0.7, -0.6), Vector3d(0.15, 0.1, 0.35)})
      {
        const RigidTransform moved(R, Vector3d(0.1, 0, 0), Vector3d(0.01, 0.02, 0.03));
        CHECK(o->gap(x, moved) == Approx(o->distance(x, moved).gap).margin(1e-15));
        Vector3d n;
        CHECK(o->gap_and_normal(x, n, moved) == Approx(o->distance(x, moved).gap).margin(1e-15));
        CHECK((n - o->distance(x, moved).normal).norm() < 1e-15);
        // closer_than is gap < d, for distances that put x inside and
        // outside the reach, and for one the reach of a round obstacle
        // cannot meet (R + d < 0).
        const double g = o->gap(x, moved);
        for (const double d : {g - 0.05, g + 0.05, -1.0, 0.0, 0.3})
          CHECK(o->closer_than(x, d, moved) == (g < d));
      }
}

TEST_CASE("obstacles refuse degenerate shapes", "[geometry][contact]")
{
  CHECK_THROWS_AS(SphereObstacle(Vector3d::Zero(), 0.0), softchain::data::InputError);
  CHECK_THROWS_AS(PlaneObstacle(Vector3d::Zero(), Vector3d::Zero()), softchain::data::InputError);
  CHECK_THROWS_AS(BoxObstacle(Vector3d::Zero(), Vector3d(1, -1, 1)), softchain::data::InputError);
}
