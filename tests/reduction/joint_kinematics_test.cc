// Joint rotations by M1 and M2 for closed-form deformations of a synthetic
// hollow finger (synthetic_finger.h): rigid motion, bending onto an arc
// about z and about y, uniform twist; degenerate and reflected slabs.
//
// Tolerance for "exact" angles: 1e-12 rad. The slabs' coordinates (<= 5e-2 m)
// are centred to slab sizes >= 2e-3 m before the fit, so the round-off of the
// sums over <= 800 nodes is ~ 1e-16 * 25 * sqrt(800) ~ 1e-13 relative, and
// SVD / atan2 add a few ulps.
#include <softchain/data/input_error.h>
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/bounding_box_frame.h>
#include <softchain/reduction/joint_frames.h>
#include <softchain/reduction/joint_layout.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "synthetic_finger.h"

using namespace softchain;
using namespace softchain::reduction;
using namespace softchain::testing;

namespace
{
  constexpr double exact = 1e-12; // rad, see the header comment
  constexpr double a     = 10 * mm;

  const std::vector<RotationMethod> both_methods = {RotationMethod::bounding_box,
                                                    RotationMethod::affine_fit};

  std::vector<SlabSelection> slabs_of(const data::MeshRecord &mesh, double b)
  {
    const JointLayout          layout(mesh.X, a, 0, "synthetic");
    std::vector<SlabSelection> slabs;
    for (int i = 1; i <= layout.n_joints(); ++i)
      slabs.emplace_back(mesh.X, i, layout.x(i), b);
    return slabs;
  }

  // Relative angles of every joint for one deformation.
  std::vector<data::JointAngles> angles_of(const SyntheticFinger &finger, RotationMethod method,
                                           double b, const Map &map)
  {
    const JointFrames frames(method, slabs_of(finger.mesh, b), finger.mesh.X,
                             deform(finger.mesh.X, map), "closed-form");
    std::vector<data::JointAngles> angles;
    for (std::size_t i = 0; i < frames.size(); ++i)
      angles.push_back(frames.relative_angles(i));
    return angles;
  }

  // Increments of the slabs' mid-abscissae m_i (the x of J_i,0), with
  // m_0 = 0 at the base. For b <= a/2 every slab lies inside the finger and
  // the increments are a (a/2 for joint 1); for b = a the slabs of the first
  // and last joints are cut by the base and tip faces and their middles move.
  std::vector<double> middle_steps(const data::MeshRecord &mesh, double b)
  {
    std::vector<double> steps;
    double              previous = 0;
    for (const auto &slab : slabs_of(mesh, b))
      {
        steps.push_back(slab.reference_centre()(0) - previous);
        previous = slab.reference_centre()(0);
      }
    return steps;
  }

  void check_angles(const data::JointAngles &got, double psi, double theta, double phi,
                    double tolerance)
  {
    CHECK(got.psi == Approx(psi).margin(tolerance));
    CHECK(got.theta == Approx(theta).margin(tolerance));
    CHECK(got.phi == Approx(phi).margin(tolerance));
  }

  // 50 mm finger, planes every 1 mm: 5 joints at 5, 15, ..., 45 mm, each slab
  // symmetric about its joint plane for b = a, a/2, a/3.
  const SyntheticFinger &uniform_finger()
  {
    static const SyntheticFinger finger = hollow_box(uniform_planes(50 * mm, 50));
    return finger;
  }
} // namespace

TEST_CASE("rigid motion: only joint 1 rotates, both methods")
{
  const data::JointAngles q{0.3, -0.2, 0.5};
  const Map               motion = rigid_motion(data::rotation_from_angles(q), {0.1, -0.02, 0.03});
  for (const auto method : both_methods)
    for (const double b : {a, a / 2, a / 3})
      {
        const auto angles = angles_of(uniform_finger(), method, b, motion);
        REQUIRE(angles.size() == 5);
        check_angles(angles[0], q.psi, q.theta, q.phi, exact);
        for (std::size_t i = 1; i < angles.size(); ++i)
          check_angles(angles[i], 0, 0, 0, exact);
      }
}

TEST_CASE("a rigid motion after bending changes joint 1 only: R_i = R_{i-1}^T R_i^0")
{
  // x = Q arc(X): R_i^0 = Q Rz(m_i/R), so R_{i-1}^T R_i^0 = Rz((m_i - m_{i-1})/R)
  // for i > 1 whatever Q, while the reversed product R_i^0 R_{i-1}^T would
  // give Q Rz(.) Q^T, with psi and theta.
  const Eigen::Matrix3d Q   = data::rotation_from_angles({0.4, 0.3, -0.2});
  const Map             arc = arc_about_z(0.2);
  const Map moved = [&](const Eigen::Vector3d &X) -> Eigen::Vector3d { return Q * arc(X); };
  for (const auto method : both_methods)
    {
      const auto angles = angles_of(uniform_finger(), method, a / 2, moved);
      for (std::size_t i = 1; i < angles.size(); ++i)
        check_angles(angles[i], 0, 0, a / 0.2, exact);
    }
}

TEST_CASE("pure bending onto an arc about z: phi_i = a / R after the first joint")
{
  // Both methods are exact here: each slab is a product of node planes
  // symmetric about its middle m_i and a cross-section symmetric in z, so in
  // the frame Rz(m_i/R) the map's x-part is odd and its y-part even in
  // s = X - m_i; the least squares fit (M2) then has no shear between x and y
  // and its polar rotation is exactly Rz(m_i/R); M1's face centroids at
  // s = +-(slab half extent) lie on one circle about the centre of curvature,
  // symmetric about the section, so their chord is along Rz(m_i/R) x too.
  // Hence phi_i = (m_i - m_{i-1}) / R, which is a / R when the slab lies
  // inside the finger (b <= a/2).
  for (const double R : {0.2, -0.08})
    for (const auto method : both_methods)
      for (const double b : {a, a / 2, a / 3})
        {
          const auto angles = angles_of(uniform_finger(), method, b, arc_about_z(R));
          const auto steps  = middle_steps(uniform_finger().mesh, b);
          for (std::size_t i = 0; i < angles.size(); ++i)
            {
              check_angles(angles[i], 0, 0, steps[i] / R, exact);
              if (b <= a / 2)
                CHECK(angles[i].phi == Approx((i == 0 ? 0.5 : 1.0) * a / R).margin(exact));
            }
        }
}

TEST_CASE("M1 on an uneven slab: chord angle error, bounded by h_max / R")
{
  // Node planes graded along x (spacing growing from 0.5 mm to ~1.5 mm), so
  // the slabs are not symmetric about x_i. M1's x edge is the chord between
  // the deformed centroids of the two end faces at X- and X+, on one circle
  // about the centre of curvature: its direction is the angle
  // (X- + X+) / (2R). Hence phi_i = (X-_i + X+_i - X-_{i-1} - X+_{i-1}) / (2R),
  // and since x_i +- b - X+- lies in [0, h_max), |phi_i - a/R| < h_max / R.
  std::vector<double> planes;
  for (double x = 0, h = 0.5 * mm; x < 50 * mm; x += h, h *= 1.023)
    planes.push_back(x);
  planes.push_back(50 * mm);
  double h_max = 0;
  for (std::size_t k = 1; k < planes.size(); ++k)
    h_max = std::max(h_max, planes[k] - planes[k - 1]);
  const SyntheticFinger finger = hollow_box(planes);
  const double          R      = 0.1;
  const double          b      = a / 2;
  const auto angles  = angles_of(finger, RotationMethod::bounding_box, b, arc_about_z(R));
  const auto slabs   = slabs_of(finger.mesh, b);
  double     largest = 0;
  for (std::size_t i = 1; i < angles.size(); ++i)
    {
      const auto   end_sum = [&](std::size_t j) {
        return slabs[j].reference_box().min()(0) + slabs[j].reference_box().max()(0);
      };
      const double predicted = (end_sum(i) - end_sum(i - 1)) / (2 * R);
      CHECK(angles[i].phi == Approx(predicted).margin(exact));
      CHECK(std::abs(angles[i].phi - a / R) < h_max / R);
      largest = std::max(largest, std::abs(angles[i].phi - a / R));
    }
  // The slabs are uneven enough to matter (measured: 2.7% of a/R).
  CHECK(largest > 1e-2 * a / R);
}

TEST_CASE("lateral bending onto an arc about y: theta_i = a / R")
{
  // As about z, with y and z exchanged: theta_i = (m_i - m_{i-1}) / R.
  const double R = 0.15;
  for (const auto method : both_methods)
    for (const double b : {a, a / 3})
      {
        const auto angles = angles_of(uniform_finger(), method, b, arc_about_y(R));
        const auto steps  = middle_steps(uniform_finger().mesh, b);
        for (std::size_t i = 0; i < angles.size(); ++i)
          check_angles(angles[i], 0, steps[i] / R, 0, exact);
        CHECK(angles[2].theta == Approx(a / R).margin(exact)); // an inner slab
      }
}

TEST_CASE("uniform twist at rate kappa: psi_i = kappa a")
{
  // Twist about the slabs' centroid axis: then, by the symmetry in s and z,
  // the fitted map is Rx(kappa m_i) diag(1, c, c) (exact polar rotation) and
  // M1's face centroids stay on / symmetric about the axis: psi_i =
  // kappa (m_i - m_{i-1}), kappa a for inner slabs.
  const double kappa = 6.0; // rad/m
  const auto  &finger = uniform_finger();
  for (const auto method : both_methods)
    for (const double b : {a, a / 2})
      {
        const auto angles =
          angles_of(finger, method, b, twist_about_x(kappa, finger.node_centroid_y()));
        const auto steps = middle_steps(finger.mesh, b);
        for (std::size_t i = 0; i < angles.size(); ++i)
          check_angles(angles[i], kappa * steps[i], 0, 0, exact);
        CHECK(angles[2].psi == Approx(kappa * a).margin(exact)); // an inner slab
      }
}

TEST_CASE("a slab of fewer than 4 nodes or of one plane is an error naming joint and sample")
{
  const auto &X = uniform_finger().mesh.X;
  // b = 0.1 mm < plane spacing 1 mm: every slab is one plane of nodes.
  for (const auto method : both_methods)
    CHECK_THROWS_WITH(JointFrames(method, slabs_of(uniform_finger().mesh, 0.1 * mm), X, X, "s7"),
                      Catch::Contains("joint 1") && Catch::Contains("sample 's7'") &&
                        Catch::Contains("one plane"));
  const std::vector<data::Point3> three = {{0, 0, 0}, {1 * mm, 0, 0}, {0, 1 * mm, 0}};
  const std::vector<SlabSelection> slab = {SlabSelection(three, 1, 0.0, a)};
  CHECK_THROWS_WITH(JointFrames(RotationMethod::affine_fit, slab, three, three, "s8"),
                    Catch::Contains("joint 1") && Catch::Contains("sample 's8'") &&
                      Catch::Contains("3 nodes"));
}

TEST_CASE("a reflected slab is an error naming joint and sample")
{
  Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
  mirror(2, 2)           = -1;
  const auto &mesh       = uniform_finger().mesh;
  const auto  x          = deform(mesh.X, rigid_motion(mirror, Eigen::Vector3d::Zero()));
  CHECK_THROWS_WITH(JointFrames(RotationMethod::affine_fit, slabs_of(mesh, a), mesh.X, x, "m"),
                    Catch::Contains("joint 1") && Catch::Contains("sample 'm'") &&
                      Catch::Contains("det A"));
  // M1's own check (JointFrames runs the affine fit, for the centre, first).
  CHECK_THROWS_WITH(BoundingBoxFrame(slabs_of(mesh, a)[2], mesh.X, x, "m"),
                    Catch::Contains("joint 3") && Catch::Contains("sample 'm'") &&
                      Catch::Contains("reflected"));
}
