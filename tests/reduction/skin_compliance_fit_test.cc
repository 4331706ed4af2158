// SkinComplianceFit against a closed form: a finger whose sections are
// squeezed through their height (the palm pushed up towards the top, which
// stays) and then turned rigidly about joint 1 gives c_s = (the palm's give)
// / (the force along the palm's normal): the squeeze turns no slab, so the
// chain's links carry the palm points rigidly and all the squeeze is skin.
// A palm that moves against its force gives c_s = 0, a skin sample without
// its pressure state is skipped; both with a warning. The shear fit (c_t)
// against a section sheared along its palm, beside a squeezed one.
#include <softchain/reduction/method_reduction.h>
#include <softchain/reduction/skin_compliance_fit.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "layer_finger_mesh.h"

using namespace softchain;
using namespace softchain::reduction;

namespace
{
  constexpr double mm = 1e-3;

  // A skin sample of the box finger (palm y = -2 mm, top y = 10 mm): its
  // nodes moved by `local`, then turned by `turn` about joint 1's centre
  // (5, 0, 0) mm; a force of `force` along the turned axis `axis` at three
  // palm points across x = 50 mm (link 5, joints at 45 and 55 mm).
  template <typename Local>
  data::SampleRecord skin_sample(const data::MeshRecord &mesh, const std::string &id, const Local &local,
                                 double turn, int axis, double force, double pressure)
  {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d J(5 * mm, 0, 0);
    data::SampleRecord    s;
    s.id                 = id;
    s.actuation.role     = "skin";
    s.actuation.pressure = pressure;
    const auto deformed  = [&](const data::Point3 &X) -> data::Point3 {
      const Eigen::Vector3d y = J + R * (local(Eigen::Vector3d(X[0], X[1], X[2])) - J);
      return {{y.x(), y.y(), y.z()}};
    };
    for (const auto &X : mesh.X)
      s.x.push_back(deformed(X));
    const Eigen::Vector3d f = force * R.col(axis);
    for (const double z : {-3 * mm, 0.0, 3 * mm})
      {
        s.actuation.point_forces.push_back({{50 * mm, -2 * mm, z}, {f.x(), f.y(), f.z()}});
        s.force_points_deformed.push_back(deformed({{50 * mm, -2 * mm, z}}));
      }
    return s;
  }

  // The box finger squeezed by y' = y + strain (10 mm - y), pressed along
  // the palm's normal.
  data::SampleRecord squeezed(const data::MeshRecord &mesh, double strain, double turn, double force,
                              double pressure)
  {
    const auto squeeze = [&](const Eigen::Vector3d &X) {
      return Eigen::Vector3d(X.x(), X.y() + strain * (10 * mm - X.y()), X.z());
    };
    return skin_sample(mesh, "skin" + std::to_string(strain), squeeze, turn, 1, force, pressure);
  }

  // The box finger whose palm (y = -2 mm) slides by `slide` along x and
  // whose top (y = 10 mm) by the same, every other node staying: the
  // section's affine fit sees no shear (the two faces lie symmetric about
  // its centre y = 4 mm), so M2's links do not turn, and the palm slides by
  // `slide` from the layer (y = 0) above it; pulled along the finger's axis.
  data::SampleRecord sheared(const data::MeshRecord &mesh, double slide, double turn, double force)
  {
    const auto slide_faces = [&](const Eigen::Vector3d &X) {
      const bool face = std::abs(X.y() + 2 * mm) < 1e-9 || std::abs(X.y() - 10 * mm) < 1e-9;
      return Eigen::Vector3d(X.x() + (face ? slide : 0.0), X.y(), X.z());
    };
    return skin_sample(mesh, "shear" + std::to_string(slide), slide_faces, turn, 0, force, 0.0);
  }

  // The normal and shear fits of the box finger's reduction of `samples`.
  std::pair<SkinComplianceFit, SkinComplianceFit> fits(const data::MeshRecord &mesh,
                                                       const std::vector<data::SampleRecord> &samples)
  {
    const ReductionParameters p = testing::layer_finger_parameters();
    const double              a = p.joint_spacing;
    const JointLayout         layout(mesh.X, a, 0, "box");
    // A lattice of a / 10 (1 mm) lies symmetric about the section's centre
    // (12 mm high), so that the slides of the palm and the top turn no link.
    const auto                body = std::make_shared<const BodySamples>(mesh, a / 10, "box");
    const MethodReduction     r(RotationMethod::affine_fit, 0.5, p, JointGeometry(layout, body, 0.0, a / 2), mesh,
                                samples);
    return {r.skin_compliance(), r.skin_shear_compliance()};
  }

  SkinComplianceFit fit(const data::MeshRecord &mesh, const std::vector<data::SampleRecord> &samples)
  {
    return fits(mesh, samples).first;
  }
} // namespace

TEST_CASE("a squeezed and turned section: c_s is the palm's give over the force along its normal")
{
  const data::MeshRecord mesh   = testing::layer_finger_mesh(false);
  const double           strain = 0.02, force = 0.1;
  // The palm (y = -2 mm) rises by strain * 12 mm relative to its link; the
  // three forces press it with 3 * force. Exact up to round-off.
  for (const double turn : {0.0, 0.4})
    {
      const SkinComplianceFit c = fit(mesh, {squeezed(mesh, strain, turn, force, 0)});
      CHECK(c.warnings().empty());
      REQUIRE(c.values().size() == 1);
      CHECK(c.values()[0].pressure == 0.0);
      CHECK(c.values()[0].samples == 1);
      CHECK(c.values()[0].compliance == Approx(strain * 12 * mm / (3 * force)).epsilon(1e-9));
      CHECK(c.table().n_rows() == 1);
    }
}

TEST_CASE("a palm that moves against its force gives c_s = 0, no pressure state no row, both warn")
{
  const data::MeshRecord mesh = testing::layer_finger_mesh(false);
  SECTION("pushed out against the force")
  {
    const SkinComplianceFit c = fit(mesh, {squeezed(mesh, -0.02, 0.0, 0.1, 0)});
    REQUIRE(c.values().size() == 1);
    CHECK(c.values()[0].compliance == 0.0);
    REQUIRE(c.warnings().size() == 1);
    CHECK_THAT(c.warnings()[0], Catch::Contains("skin compliance at 0 Pa set to 0"));
  }
  SECTION("at a pressure without a pressure sample")
  {
    const SkinComplianceFit c = fit(mesh, {squeezed(mesh, 0.02, 0.0, 0.1, 2e4)});
    CHECK(c.values().empty());
    REQUIRE(c.warnings().size() == 1);
    CHECK_THAT(c.warnings()[0], Catch::Contains("skin sample 'skin0.020000' at 20000 Pa skipped"));
  }
}

TEST_CASE("a section sheared along its palm: c_t is the palm's slide from the layer over the force along it")
{
  const data::MeshRecord mesh  = testing::layer_finger_mesh(false);
  const double           slide = 0.05 * mm, force = 0.1;
  // Exact up to round-off: the palm points and the layer above them are
  // nodes or lie on faces whose nodes all move alike.
  for (const double turn : {0.0, 0.4})
    {
      const auto [normal, shear] = fits(mesh, {sheared(mesh, slide, turn, force), squeezed(mesh, 0.02, turn, force, 0)});
      CHECK(shear.warnings().empty());
      REQUIRE(shear.values().size() == 1);
      CHECK(shear.values()[0].samples == 1); // the squeeze presses, and is the normal fit's
      CHECK(shear.values()[0].compliance == Approx(slide / (3 * force)).epsilon(1e-9));
      // The normal fit takes the squeeze alone: its value as without the shear.
      REQUIRE(normal.values().size() == 1);
      CHECK(normal.values()[0].samples == 1);
      CHECK(normal.values()[0].compliance == Approx(0.02 * 12 * mm / (3 * force)).epsilon(1e-9));
    }
  // A palm that slides against its pull: c_t = 0, with the shear fit's warning.
  const SkinComplianceFit against = fits(mesh, {sheared(mesh, -slide, 0.0, force)}).second;
  REQUIRE(against.values().size() == 1);
  CHECK(against.values()[0].compliance == 0.0);
  REQUIRE(against.warnings().size() == 1);
  CHECK_THAT(against.warnings()[0], Catch::Contains("skin shear compliance at 0 Pa set to 0"));
}
