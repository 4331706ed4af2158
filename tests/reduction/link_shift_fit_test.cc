// LinkShiftFit: the ridge least-squares slope of a link's change against its
// joint's in-plane turn, against its closed form; at rest, where the pressure
// turns no joint, no shift.
#include <softchain/data/tip_pose_fit.h>
#include <softchain/reduction/link_shift_fit.h>

#include <catch2/catch.hpp>

#include "layer_finger_mesh.h"
#include "synthetic_finger.h"

using namespace softchain;
using namespace softchain::reduction;

TEST_CASE("the shift per turn is the ridge slope sum dphi dU / (sum dphi^2 + resolution^2)")
{
  const Eigen::Vector2d g(2e-3, -3e-3); // m/rad
  std::vector<LinkShiftFit::Observation> observations;
  double                                 squared = 0.0;
  for (const double turn : {0.05, -0.1, 0.2})
    {
      observations.push_back({turn, g * turn});
      squared += turn * turn;
    }
  const double    r2       = LinkShiftFit::turn_resolution * LinkShiftFit::turn_resolution;
  const auto      expected = (g * squared / (squared + r2)).eval();
  const Eigen::Vector2d fitted = LinkShiftFit::shift_per_turn(observations);
  // Closed form, round-off only.
  CHECK((fitted - expected).norm() <= 1e-15);
  // Turns far above the resolution recover g within the ridge's shrink
  // r2 / sum dphi^2 = 1e-4 / 0.0525 = 0.19 %.
  CHECK((fitted - g).norm() <= 0.002 * g.norm());
  // A turn below the resolution is shrunk, not amplified: 1 mm of noise at a
  // turn of 1e-4 rad reads 1e-4 * 1e-3 / (1e-8 + 1e-4) ~ 1e-3 m/rad, not 10.
  const Eigen::Vector2d noisy = LinkShiftFit::shift_per_turn({{1e-4, Eigen::Vector2d(1e-3, 0.0)}});
  CHECK(noisy.norm() <= 1.0001e-3);
  CHECK(LinkShiftFit::shift_per_turn({}) == Eigen::Vector2d::Zero());
}

TEST_CASE("at rest the links do not shift")
{
  const data::MeshRecord mesh = reduction::testing::layer_finger_mesh(false);
  const Eigen::Vector3d  tip  = data::TipPoseFit::of_mesh(mesh, "box").reference_centroid();
  // Bent onto an arc of radius 0.2 m: every joint turns by 0.05 rad.
  const softchain::testing::Map arc = softchain::testing::arc_about_z(0.2);
  const Eigen::Vector3d bent_tip = arc(tip);
  data::SampleRecord    s;
  s.id                     = "arc";
  s.actuation.role         = "chord";
  s.x                      = softchain::testing::deform(mesh.X, arc);
  s.actuation.point_forces = {{{tip.x(), tip.y(), tip.z()}, {0.0, 0.5, 0.0}}};
  s.force_points_deformed  = {{bent_tip.x(), bent_tip.y(), bent_tip.z()}};
  const double          a = 0.01;
  const JointLayout     layout(mesh.X, a, 0, "box");
  const auto            body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
  const auto            parameters = reduction::testing::layer_finger_parameters();
  const MethodReduction r(RotationMethod::affine_fit, 0.5, parameters, JointGeometry(layout, body, 0.0, a / 2), mesh,
                          {s});
  const LinkShiftFit    fit(r, parameters);
  CHECK(fit.warnings().empty());
  REQUIRE(fit.values().size() == 1);
  const LinkShiftAtPressure &v = fit.values().front();
  CHECK(v.samples == 1);
  REQUIRE(v.shift.size() == r.rest().link_geometry().size() - 1);
  for (std::size_t i = 0; i < v.shift.size(); ++i)
    {
      // The sample turns the joints, but the rest state does not: no
      // observation, no shift.
      CHECK(std::abs(r.samples().front().joints()[i].angles.phi) > 0.01);
      CHECK(v.turn_rms[i] == 0.0);
      CHECK(v.shift[i] == Eigen::Vector2d::Zero());
    }
  CHECK(fit.table().n_rows() == v.shift.size());
}
