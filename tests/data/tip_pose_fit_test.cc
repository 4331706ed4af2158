// The FEM tip frame fitted to coplanar tip nodes, and rotation angles.
#include <softchain/data/tip_pose_fit.h>

#include <Eigen/Geometry>

#include <catch2/catch.hpp>

using namespace softchain::data;

namespace
{
  // A tip face: a 3 x 4 grid in the plane x = 0.09.
  std::vector<Eigen::Vector3d> tip_face()
  {
    std::vector<Eigen::Vector3d> nodes;
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 4; ++k)
        nodes.emplace_back(0.09, 0.004 * j - 0.002, 0.005 * k - 0.007);
    return nodes;
  }
} // namespace

TEST_CASE("a rigid motion of the coplanar tip face is recovered exactly")
{
  const std::vector<Eigen::Vector3d> reference = tip_face();
  const TipPoseFit                   fit(reference);
  // 200 deg about a skew axis: beyond half a turn of bending.
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(200.0 * M_PI / 180.0, Eigen::Vector3d(0.2, -0.3, 1.0).normalized())
      .toRotationMatrix();
  const Eigen::Vector3d        t(-0.03, 0.05, 0.01);
  std::vector<Eigen::Vector3d> deformed;
  for (const Eigen::Vector3d &X : reference)
    deformed.push_back(R * X + t);
  const TipPose pose = fit.fit(deformed);
  // Round-off of an SVD of O(1e-5) sums and of products of O(0.1 m) lengths.
  CHECK((pose.rotation - R).norm() < 1e-12);
  CHECK((pose.position - (R * fit.reference_centroid() + t)).norm() < 1e-14);
  CHECK(rotation_angle_between(Eigen::Matrix3d::Identity(), pose.rotation) ==
        Approx(160.0 * M_PI / 180.0).epsilon(1e-12)); // 200 deg is 160 deg the other way
}

TEST_CASE("rotation angles are accurate at small angles too")
{
  for (const double angle : {1e-9, 1e-4, 0.5, 3.0})
    {
      const Eigen::Matrix3d a =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      const Eigen::Matrix3d b =
        a * Eigen::AngleAxisd(angle, Eigen::Vector3d(-1, 0, 2).normalized()).toRotationMatrix();
      // atan2 form: relative round-off ~ eps / angle... bounded by 1e-7 at 1e-9 rad.
      CHECK(rotation_angle_between(a, b) == Approx(angle).epsilon(1e-6));
    }
}

TEST_CASE("collinear tip nodes do not define a frame")
{
  CHECK_THROWS_AS(TipPoseFit({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}}), std::invalid_argument);
}
