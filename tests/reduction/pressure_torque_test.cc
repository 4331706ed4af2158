// J_p from the cavity geometry. Reference result: for a closed cavity
// surface, uniform pressure has zero resultant and zero moment, so the walls
// distal to a section plane (normal n, through J) carry the opposite of what
// the plane's cap would: force p A_cap n and moment p A_cap (c_cap - J) x n,
// with A_cap and c_cap the area and centroid of the cavity's section. For the
// prismatic cavity of synthetic_finger.h (section 6 mm x 6 mm, centroid
// y = 1 mm, z = 0) cut by a plane of normal n: A_cap = A / |n_x| and c_cap is
// where the centroid line (y = 1 mm, z = 0) meets the plane.
//
// Tolerance: 1e-12 of the moment's scale A * 1 mm. The sum runs over ~400
// triangles whose moments are at most A_t * L ~ 1e-6 * 5e-2 while the result
// is ~ 3.6e-8 (ratio ~ 1): round-off ~ 400 * 1e-16 relative, 1e-12 leaves
// a margin of 25.
#include <softchain/reduction/pressure_torque.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "synthetic_finger.h"

using namespace softchain;
using namespace softchain::reduction;
using namespace softchain::testing;

namespace
{
  constexpr double scale     = cavity_area * 1 * mm;
  constexpr double tolerance = 1e-12 * scale;

  // Moment per pascal, world axes, of the cap of the cavity section by the
  // plane through J with normal n.
  Eigen::Vector3d cap_moment(const Eigen::Vector3d &J, const Eigen::Vector3d &n)
  {
    // c_cap = (x, 1 mm, 0) with (c_cap - J) . n = 0.
    const double          x = J(0) - ((cavity_centroid_y - J(1)) * n(1) - J(2) * n(2)) / n(0);
    const Eigen::Vector3d c(x, cavity_centroid_y, 0);
    return cavity_area / std::abs(n(0)) * (c - J).cross(n);
  }

  // A frame whose x axis is the plane normal.
  Eigen::Matrix3d tilted_frame(double about_z, double about_y)
  {
    return (Eigen::AngleAxisd(about_z, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(about_y, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
  }
} // namespace

TEST_CASE("J_p of a straight prismatic cavity at rest is A times the centroid offset")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  const PressureTorque  jp(finger.mesh.cavity_triangles, finger.mesh.X);
  // Section planes at the joints (node planes) and between node planes, so
  // that the wall triangles are clipped.
  for (const double x : {5 * mm, 15 * mm, 22.3 * mm, 44.9 * mm})
    {
      const Eigen::Vector3d J(x, 0, 0);
      const Eigen::Vector3d got = jp.per_pascal(J, Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitX());
      // p A (c - J) x e_x with c - J = (0, 1 mm, 0): -A * 1 mm about z.
      CHECK(got(0) == Approx(0).margin(tolerance));
      CHECK(got(1) == Approx(0).margin(tolerance));
      CHECK(got(2) == Approx(-cavity_area * cavity_centroid_y).margin(tolerance));
      // Inflation pushes the distal end cap distally, above the centre line:
      // the finger bends toward -y, a negative rotation about z.
      CHECK(got(2) < 0);
    }
  // About a point off the centre line in z, the moment about y appears:
  // (c - J) x e_x = (0, 1 mm, 2 mm) x e_x = (0, 2 mm, -1 mm).
  const Eigen::Vector3d got = jp.per_pascal({30 * mm, 0, -2 * mm}, Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitX());
  CHECK(got(1) == Approx(cavity_area * 2 * mm).margin(tolerance));
}

TEST_CASE("J_p of the closed cavity cut at several planes, tilted and rotated")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  const PressureTorque  jp(finger.mesh.cavity_triangles, finger.mesh.X);
  for (const double about_z : {0.0, 0.2, -0.35})
    for (const double about_y : {0.0, 0.25})
      for (const Eigen::Vector3d &J : {Eigen::Vector3d(12.3 * mm, 0.4 * mm, -0.7 * mm),
                                      Eigen::Vector3d(31.7 * mm, -3 * mm, 1 * mm)})
        {
          const Eigen::Matrix3d frame = tilted_frame(about_z, about_y);
          const Eigen::Vector3d got   = jp.per_pascal(J, frame, frame.col(0));
          const Eigen::Vector3d want  = frame.transpose() * cap_moment(J, frame.col(0));
          CHECK((got - want).norm() < tolerance);
        }
  // Planes before the cavity and beyond it: the whole closed surface, then
  // none of it, is distal; both carry no moment.
  for (const double x : {-1 * mm, 51 * mm})
    CHECK(jp.per_pascal({x, 0, 0}, tilted_frame(0.1, 0.1), tilted_frame(0.1, 0.1).col(0)).norm() < tolerance);
}

TEST_CASE("J_p turns with a rigid motion of finger and joint frame")
{
  const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
  const Eigen::Matrix3d Q      = tilted_frame(0.7, -0.4);
  const Eigen::Vector3d t(0.01, 0.02, -0.03);
  const auto            moved = deform(finger.mesh.X, rigid_motion(Q, t));
  const Eigen::Vector3d J(22.3 * mm, 0, 0);
  const Eigen::Vector3d at_rest =
    PressureTorque(finger.mesh.cavity_triangles, finger.mesh.X).per_pascal(J, Eigen::Matrix3d::Identity(), Eigen::Vector3d::UnitX());
  const Eigen::Vector3d after =
    PressureTorque(finger.mesh.cavity_triangles, moved).per_pascal(Q * J + t, Q, Q.col(0));
  // In the joint frame J_p does not change: the joint frame moves with the body.
  CHECK((after - at_rest).norm() < tolerance);
}
