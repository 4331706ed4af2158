// LinkComplianceFit against a closed form: a finger stretched uniformly along
// its axis by a chord sample's pull gives c = (tip's stretch) / force, with
// the joints unturned; a pull the links give against gives c = 0 (the
// non-negative least-squares value), a chord sample without its pressure
// state is skipped; both with a warning.
#include <softchain/data/tip_pose_fit.h>
#include <softchain/reduction/link_compliance_fit.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "layer_finger_mesh.h"

using namespace softchain;
using namespace softchain::reduction;

namespace
{
  constexpr double mm = 1e-3;
  constexpr double a  = 10 * mm; // joint spacing

  ReductionParameters parameters() { return testing::layer_finger_parameters(); }

  // The finger stretched along x by the factor 1 + strain about the clamp
  // (x = 0), pulled at its tip centroid by `force` (role chord).
  data::SampleRecord stretched(const data::MeshRecord &mesh, double strain, double pressure,
                               const Eigen::Vector3d &tip, const Eigen::Vector3d &force)
  {
    data::SampleRecord s;
    s.id                 = "chord" + std::to_string(strain);
    s.actuation.role     = "chord";
    s.actuation.pressure = pressure;
    for (const auto &X : mesh.X)
      s.x.push_back({(1 + strain) * X[0], X[1], X[2]});
    s.actuation.point_forces = {{{tip.x(), tip.y(), tip.z()}, {force.x(), force.y(), force.z()}}};
    s.force_points_deformed  = {{(1 + strain) * tip.x(), tip.y(), tip.z()}};
    return s;
  }

  MethodReduction reduce(const data::MeshRecord &mesh, const std::vector<data::SampleRecord> &samples)
  {
    const JointLayout layout(mesh.X, a, 0, "box");
    const auto        body = std::make_shared<const BodySamples>(mesh, a / 8, "box");
    return MethodReduction(RotationMethod::affine_fit, 0.5, parameters(),
                           JointGeometry(layout, body, 0.0, a / 2), mesh, samples);
  }
} // namespace

TEST_CASE("a uniform stretch along a pulling force: c is the tip's stretch over the force")
{
  const data::MeshRecord mesh = testing::layer_finger_mesh(false);
  const Eigen::Vector3d  tip  = data::TipPoseFit::of_mesh(mesh, "box").reference_centroid();
  const double           strain = 0.01, force = 0.5;
  // At p = 0 the pressure state is the rest configuration. A uniform
  // stretch turns no frame (its polar rotation is the identity), so the
  // chain of rest links lands at the reference tip; the FEM's tip moved by
  // strain * x_T along x. Exact up to round-off (1e-12 relative).
  const MethodReduction r =
    reduce(mesh, {stretched(mesh, strain, 0, tip, Eigen::Vector3d(force, 0, 0)),
                  stretched(mesh, 2 * strain, 0, tip, Eigen::Vector3d(2 * force, 0, 0))});
  const LinkComplianceFit fit(r, parameters());
  CHECK(fit.warnings().empty());
  REQUIRE(fit.values().size() == 1);
  CHECK(fit.values()[0].pressure == 0.0);
  CHECK(fit.values()[0].samples == 2);
  CHECK(fit.values()[0].compliance == Approx(strain * tip.x() / force).epsilon(1e-12));
  // The rest chord runs from joint 1's centre to the tip centroid.
  const Eigen::Vector3d chord = tip - r.rest().link_geometry().front();
  CHECK(fit.values()[0].chord_angle ==
        Approx(std::atan2(chord.tail<2>().norm(), chord.x()) * 180 / M_PI).epsilon(1e-12));
  CHECK(fit.table().n_rows() == 1);
}

TEST_CASE("a force the links give against gives c = 0, no pressure state no row, both warn")
{
  const data::MeshRecord mesh = testing::layer_finger_mesh(false);
  const Eigen::Vector3d  tip  = data::TipPoseFit::of_mesh(mesh, "box").reference_centroid();
  SECTION("stretched against a push")
  {
    const MethodReduction   r = reduce(mesh, {stretched(mesh, 0.01, 0, tip, Eigen::Vector3d(-0.5, 0, 0))});
    const LinkComplianceFit fit(r, parameters());
    REQUIRE(fit.values().size() == 1);
    CHECK(fit.values()[0].compliance == 0.0);
    REQUIRE(fit.warnings().size() == 1);
    CHECK_THAT(fit.warnings()[0], Catch::Contains("link compliance at 0 Pa set to 0"));
  }
  SECTION("at a pressure without a pressure sample")
  {
    const MethodReduction   r = reduce(mesh, {stretched(mesh, 0.01, 2e4, tip, Eigen::Vector3d(0.5, 0, 0))});
    const LinkComplianceFit fit(r, parameters());
    CHECK(fit.values().empty());
    REQUIRE(fit.warnings().size() == 1);
    CHECK_THAT(fit.warnings()[0], Catch::Contains("chord sample 'chord0.010000' at 20000 Pa skipped"));
  }
}
