// TriangulatedObstacle (Shape = stl) against the analytic obstacles it
// approximates or equals, and RigidTransform (obstacles turning along the
// load path):
//  - a box's surface gives BoxObstacle's distance, normal and curvature to
//    round-off, outside and inside; a tessellated sphere SphereObstacle's
//    within its chord error;
//  - the bounding-volume tree finds the triangle a scan over all of them
//    finds;
//  - n = grad g and H = grad n by central differences on a face, an edge
//    and a vertex region, and for a turned and moved obstacle;
//  - open, inconsistently oriented and degenerate meshes are refused with
//    the file's name; an inward-wound mesh is turned outward.
#include "obstacle_meshes.h"
#include "test_files.h"

#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>
#include <softchain/geometry/contact_scene.h>
#include <softchain/geometry/rigid_obstacle.h>
#include <softchain/geometry/triangle_closest_point.h>
#include <softchain/geometry/triangulated_obstacle.h>

#include <catch2/catch.hpp>

#include <random>

using namespace softchain::geometry;
using softchain::data::InputError;
using Eigen::Vector3d;

namespace
{
  // Points uniformly at random in the box [-size, size]^3 about `center`.
  std::vector<Vector3d> random_points(const Vector3d &center, const double size, const int count,
                                      const unsigned seed)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> coordinate(-size, size);
    std::vector<Vector3d>                  points;
    for (int k = 0; k < count; ++k)
      points.push_back(center + Vector3d(coordinate(random), coordinate(random), coordinate(random)));
    return points;
  }

  // Central differences with step h = 1e-6 at distances and curvature
  // radii of order 0.1 to 1: truncation below 1e-9, round-off 1e-10; the
  // points lie farther than h from the borders of their feature's region
  // (where H jumps).
  template <typename Distance>
  void check_derivatives(const Distance &distance, const Vector3d &x)
  {
    const double         h = 1e-6;
    const SignedDistance d = distance(x);
    for (int j = 0; j < 3; ++j)
      {
        Vector3d e = Vector3d::Zero();
        e[j]       = h;
        const SignedDistance plus = distance(x + e), minus = distance(x - e);
        CHECK((plus.gap - minus.gap) / (2 * h) == Approx(d.normal[j]).margin(1e-6));
        for (int i = 0; i < 3; ++i)
          CHECK((plus.normal[i] - minus.normal[i]) / (2 * h) == Approx(d.hessian(i, j)).margin(1e-6));
      }
    CHECK(d.normal.norm() == Approx(1.0).epsilon(1e-14));
  }
} // namespace

TEST_CASE("a box's triangle surface has the box's signed distance", "[geometry][contact][stl]")
{
  const Vector3d        c(0.1, -0.2, 0.3), h(1, 2, 3);
  const Eigen::Matrix3d R = RigidTransform::rotation_of(Vector3d(0.2, -0.4, 0.3));
  const BoxObstacle     box(c, h, R);
  const TriangulatedObstacle mesh(testing::box_surface(c, h, R).triangles, "box.stl");
  CHECK(mesh.volume() == Approx(8 * h.prod()).epsilon(1e-14));
  int inside = 0;
  for (const Vector3d &x : random_points(c, 4, 2000, 1))
    {
      const SignedDistance a = mesh.distance_at_rest(x), b = box.distance_at_rest(x);
      inside += b.gap < 0;
      CHECK(a.gap == Approx(b.gap).margin(1e-13));
      CHECK((a.normal - b.normal).norm() < 1e-12);
      CHECK((a.hessian - b.hessian).norm() < 1e-10 * (1 + b.hessian.norm()));
    }
  CHECK(inside > 100); // the inside is covered, not only the outside
}

TEST_CASE("a tessellated sphere has the sphere's distance within its chord error", "[geometry][contact][stl]")
{
  const Vector3d             c(0.3, 0.1, -0.2);
  const double               R = 0.5;
  const auto                 stl = testing::sphere_surface(c, R, 5); // 8192 triangles
  const TriangulatedObstacle mesh(stl.triangles, "sphere.stl");
  const SphereObstacle       sphere(c, R);
  // The polyhedron lies between the sphere and the ball of radius r_in (the
  // least distance of c to a face's plane), so |g - g_sphere| <= R - r_in.
  double r_in = R;
  for (const auto &t : stl.triangles)
    r_in = std::min(r_in, std::abs((t[1] - t[0]).cross(t[2] - t[0]).normalized().dot(t[0] - c)));
  const double chord = R - r_in;
  INFO("chord error " << chord / R << " R");
  CHECK(chord < 2e-3 * R);
  CHECK(mesh.volume() < 4.0 / 3 * M_PI * R * R * R);
  CHECK(mesh.volume() > 4.0 / 3 * M_PI * r_in * r_in * r_in);
  for (const Vector3d &x : random_points(c, 2 * R, 2000, 2))
    {
      const SignedDistance a = mesh.distance_at_rest(x), b = sphere.distance_at_rest(x);
      CHECK(std::abs(a.gap - b.gap) <= chord * (1 + 1e-12));
    }
}

TEST_CASE("the bounding-volume tree finds the nearest triangle", "[geometry][contact][stl]")
{
  const auto                 stl = testing::sphere_surface(Vector3d::Zero(), 1, 3);
  const TriangulatedObstacle mesh(stl.triangles, "sphere.stl");
  for (const Vector3d &x : random_points(Vector3d::Zero(), 3, 500, 3))
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto &t : stl.triangles)
        nearest = std::min(nearest, (x - closest_point_on_triangle(x, t[0], t[1], t[2]).point).norm());
      CHECK(std::abs(mesh.distance_at_rest(x).gap) == Approx(nearest).epsilon(1e-14));
    }
}

TEST_CASE("a triangle surface's normal and curvature are its distance's derivatives", "[geometry][contact][stl]")
{
  // A coarse sphere (32 triangles): its edges and vertices are not flat.
  const auto                 stl = testing::sphere_surface(Vector3d::Zero(), 1, 1);
  const TriangulatedObstacle mesh(stl.triangles, "sphere.stl");
  const auto distance = [&](const Vector3d &x) { return mesh.distance_at_rest(x); };
  const StlFile::Triangle &t = stl.triangles[5];
  const Vector3d centroid = (t[0] + t[1] + t[2]) / 3, mid = (t[0] + t[1]) / 2, skew(0.011, -0.007, 0.013);
  check_derivatives(distance, 1.4 * centroid + skew);  // face, outside
  check_derivatives(distance, 0.5 * centroid + skew);  // face, inside
  check_derivatives(distance, 1.6 * mid.normalized() + skew); // edge
  check_derivatives(distance, 1.7 * t[0] + skew);      // vertex
  CHECK(distance(1.4 * centroid + skew).hessian.norm() == 0);
  CHECK(distance(1.6 * mid.normalized() + skew).hessian.norm() > 0.1);
  CHECK(distance(1.7 * t[0] + skew).hessian.norm() > 0.1);
}

TEST_CASE("a turned and moved obstacle: the rest distance seen through its pose", "[geometry][contact]")
{
  // The pose of the path parameter t = 0.7 of a turn w about p and a
  // translation c: x = R (y - p) + p + t c with R = exp(0.7 [w]x).
  const Vector3d       w(0.3, -0.5, 0.4), p(0.2, 0.1, -0.3), c(0.05, 0.1, -0.2);
  const RigidTransform pose = RigidTransform::along_path(0.7, w, p, c);
  const Eigen::Matrix3d R   = pose.rotation();
  CHECK((R - Eigen::AngleAxisd(0.7 * w.norm(), w.normalized()).toRotationMatrix()).norm() < 1e-15);
  CHECK((RigidTransform::along_path(0, w, p, c).rotation() - Eigen::Matrix3d::Identity()).norm() == 0);
  const BoxObstacle box(Vector3d(0.1, -0.2, 0.3), Vector3d(1, 2, 3));
  for (const Vector3d &y : {Vector3d(0.3, 2.4, -1.0), Vector3d(1.5, 2.7, 0.2), Vector3d(1.4, -2.3, 3.5),
                            Vector3d(0.1, 1.7, 0.2)})
    {
      const Vector3d x = pose.to_world(y);
      CHECK((pose.to_rest(x) - y).norm() < 1e-14);
      CHECK((x - (R * (y - p) + p + 0.7 * c)).norm() < 1e-14);
      const SignedDistance moved = box.distance(x, pose), rest = box.distance_at_rest(y);
      CHECK(moved.gap == Approx(rest.gap).margin(1e-14));
      CHECK((moved.normal - R * rest.normal).norm() < 1e-14);
      check_derivatives([&](const Vector3d &z) { return box.distance(z, pose); }, x);
    }
}

TEST_CASE("open, inconsistently oriented and degenerate surfaces are refused", "[geometry][contact][stl]")
{
  const StlFile box = testing::box_surface(Vector3d::Zero(), Vector3d(1, 1, 1));
  StlFile       open = box;
  open.triangles.pop_back();
  CHECK_THROWS_WITH(TriangulatedObstacle(open.triangles, "open.stl"),
                    Catch::Contains("open.stl") && Catch::Contains("not closed"));
  StlFile twisted = box;
  std::swap(twisted.triangles[3][1], twisted.triangles[3][2]);
  CHECK_THROWS_WITH(TriangulatedObstacle(twisted.triangles, "twisted.stl"),
                    Catch::Contains("twisted.stl") && Catch::Contains("not consistently oriented"));
  StlFile flat = box;
  flat.triangles.push_back({{Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2)}});
  CHECK_THROWS_WITH(TriangulatedObstacle(flat.triangles, "flat.stl"),
                    Catch::Contains("flat.stl") && Catch::Contains("no area"));
  CHECK_THROWS_AS(TriangulatedObstacle({}, "empty.stl"), InputError);

  // Wound inward: turned outward, the same distances.
  StlFile inward = box;
  for (auto &t : inward.triangles)
    std::swap(t[1], t[2]);
  const TriangulatedObstacle outward(box.triangles, "box.stl"), turned(inward.triangles, "inward.stl");
  for (const Vector3d &x : {Vector3d(0.2, 0.3, 0.1), Vector3d(2, 0.5, -3)})
    {
      CHECK(turned.distance_at_rest(x).gap == Approx(outward.distance_at_rest(x).gap).margin(1e-15));
      CHECK((turned.distance_at_rest(x).normal - outward.distance_at_rest(x).normal).norm() < 1e-15);
    }
  CHECK(turned.volume() == Approx(8));
}

TEST_CASE("Shape = stl reads its file beside the .prm and turns along the load path", "[geometry][contact][stl]")
{
  const std::string dir = testing::scratch_directory("stl_obstacle");
  testing::box_surface(Vector3d::Zero(), Vector3d(0.01, 0.02, 0.03)).write(dir + "/crate.stl");
  const Vector3d position(0.05, -0.04, 0), rotation(0, 0, 0.3);
  testing::write_text(dir + "/scene.prm", "subsection Contact\n"
                                          "  subsection crate\n"
                                          "    set Shape = stl\n"
                                          "    set File = crate.stl\n"
                                          "    set Position = 0.05, -0.04, 0\n"
                                          "    set Rotation = 0, 0, 0.3\n"
                                          "    set Motion = 0, 0.001, 0\n"
                                          "    set Motion rotation = 0.1, 0, 0\n"
                                          "  end\n"
                                          "  subsection table\n"
                                          "    set Shape = plane\n"
                                          "    set Motion rotation = 0, 0, 0.2\n"
                                          "    set Motion pivot = 0.01, 0, 0\n"
                                          "  end\n"
                                          "end\n");
  const ContactScene scene = ContactScene::read(softchain::data::PrmFile::read(dir + "/scene.prm"));
  const Obstacle    &crate = *scene.find("crate");
  CHECK(crate.description.vertices.size() == 36);
  CHECK(crate.description.file == dir + "/crate.stl");
  // The pivot defaults to Position.
  CHECK(crate.description.motion_pivot == softchain::data::Point3{0.05, -0.04, 0});
  CHECK(scene.find("table")->description.motion_pivot == softchain::data::Point3{0.01, 0, 0});
  const BoxObstacle box(position, Vector3d(0.01, 0.02, 0.03), RigidTransform::rotation_of(rotation));
  const RigidTransform pose = crate.pose(0.5);
  CHECK((pose.rotation() - RigidTransform::rotation_of(Vector3d(0.05, 0, 0))).norm() < 1e-15);
  for (const Vector3d &x : random_points(position, 0.05, 200, 4))
    {
      const SignedDistance a = crate.body->distance(x, pose), b = box.distance(x, pose);
      CHECK(a.gap == Approx(b.gap).margin(1e-15));
      CHECK((a.normal - b.normal).norm() < 1e-12);
    }

  testing::write_text(dir + "/missing.prm", "subsection Contact\n  subsection stone\n    set Shape = stl\n"
                                            "    set File = stone.stl\n  end\nend\n");
  CHECK_THROWS_WITH(ContactScene::read(softchain::data::PrmFile::read(dir + "/missing.prm")),
                    Catch::Contains("missing.prm:4") && Catch::Contains("stone.stl"));
  auto open = testing::box_surface(Vector3d::Zero(), Vector3d(0.01, 0.01, 0.01));
  open.triangles.erase(open.triangles.begin());
  open.write(dir + "/stone.stl");
  CHECK_THROWS_WITH(ContactScene::read(softchain::data::PrmFile::read(dir + "/missing.prm")),
                    Catch::Contains("stone.stl") && Catch::Contains("not closed"));
}
