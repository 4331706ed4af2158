// The chain's link geometry (SampleReduction::link_geometry): the chain,
// its links turned by the sample's own joint angles, lands on the sample's
// deformed joint centres, tip centroid and tip frame, however the finger
// stretches and shears between its joints.
#include <softchain/data/joint_angles.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/vector_of_point.h>
#include <softchain/reduction/sample_reduction.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>

#include "layer_finger_mesh.h"

using namespace softchain;
using namespace softchain::reduction;

namespace
{
  constexpr double mm = 1e-3;
  constexpr double a  = 10 * mm; // joint spacing

  // The layer finger stretched along x by 2-4 % (more at the top: it bends
  // like an inflated finger), sheared down by 2 % of x, then rolled onto an
  // arc of curvature 8 rad/m about z (the tip turns by 0.7 rad): no rigid
  // link between reference joint centres follows it.
  data::SampleRecord stretched_bent_sample(const data::MeshRecord &mesh, const bool loaded)
  {
    data::SampleRecord s;
    s.id             = loaded ? "loaded" : "unloaded";
    s.actuation.role = "pressure";
    const double kappa = 8.0;
    for (const auto &P : mesh.X)
      {
        const Eigen::Vector3d X = data::vector_of(P);
        const double          arc   = X.x() * (1.02 + 2.0 * X.y());
        const double          h     = X.y() - 0.02 * X.x();
        const double          angle = kappa * arc;
        const Eigen::Vector3d on_layer(std::sin(angle) / kappa, -(1 - std::cos(angle)) / kappa, X.z());
        const Eigen::Vector3d normal(std::sin(angle), std::cos(angle), 0.0);
        const Eigen::Vector3d x = on_layer + h * normal;
        s.x.push_back({x(0), x(1), x(2)});
      }
    if (loaded) // a tip force: every joint carries torque, so every joint turns
      {
        s.actuation.point_forces = {{{88 * mm, 6 * mm, 0}, {0, -0.2, 0.05}}};
        s.force_points_deformed  = {{88 * mm, 6 * mm, 0}};
      }
    return s;
  }
} // namespace

TEST_CASE("the link geometry carries the chain onto the FEM's joints, tip and tip frame")
{
  const data::MeshRecord mesh = testing::layer_finger_mesh(false);
  const JointLayout      layout(mesh.X, a, 0, "box");
  const auto             body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
  const JointGeometry    geometry(layout, body, 0.0, a / 2);
  const data::TipPoseFit tip_fit = data::TipPoseFit::of_mesh(mesh, "box");
  for (const bool loaded : {true, false})
    {
      INFO((loaded ? "a tip force: every joint turns" : "no load: no joint carries torque"));
      const data::SampleRecord sample = stretched_bent_sample(mesh, loaded);
      const SampleReduction    reduced(sample, mesh, geometry, RotationMethod::affine_fit);
      const JointFrames frames(RotationMethod::affine_fit, geometry.slabs(), geometry.reference_points(),
                               geometry.points(sample.x), sample.id);
      const auto &U = reduced.link_geometry();
      const std::size_t n = reduced.joints().size();
      REQUIRE(U.size() == n + 1);
      // The chain's forward kinematics (chain/kinematic_chain.h):
      //   R_i = R_i-1 E(q_i),  c_1 = U_1,  c_i+1 = c_i + R_i (U_i+1 - U_i).
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
      Eigen::Vector3d c = U[0];
      double          largest_angle = 0;
      for (std::size_t i = 0; i < n; ++i)
        {
          INFO("joint " << i + 1);
          // Exact up to round-off (sums of products of O(1e-2) m numbers).
          CHECK((c - geometry.deformed_centre(i, frames, sample.x)).norm() < 1e-14);
          R = R * data::rotation_from_angles(reduced.joints()[i].angles);
          c += R * (U[i + 1] - U[i]);
          largest_angle = std::max(largest_angle, std::abs(reduced.joints()[i].angles.phi));
        }
      const data::TipPose fem_tip = tip_fit.fit(data::select_nodes(sample.x, mesh.tip_nodes));
      CHECK((c - fem_tip.position).norm() < 1e-14);
      const Eigen::Vector3d q = reduced.tip_frame();
      const Eigen::Matrix3d tip_frame =
        q.norm() > 0 ? Eigen::Matrix3d(Eigen::AngleAxisd(q.norm(), q.normalized())) : Eigen::Matrix3d::Identity();
      CHECK(data::rotation_angle_between(R * tip_frame, fem_tip.rotation) < 1e-12);
      // The links did have to stretch: a rigid reference link would miss.
      CHECK(std::abs((U[2] - U[1]).norm() - a) > 0.01 * a);
      CHECK((largest_angle > 0.05) == loaded);
    }
}
