// FabricHingeFit on synthetic increments: samples made by a known fabric
// hinge (coupled, one or both edges taut) give that hinge back, so does an
// inflated finger's pre-stressed layer that gives (its in-plane tangent
// held, the torsion samples' tilt left out), samples past a limit point are
// left out, linear springs are recovered as linear at rest and give no
// inflated law.
#include <softchain/reduction/fabric_hinge_fit.h>

#include <catch2/catch.hpp>

using softchain::data::FabricHinge;
using softchain::reduction::FabricHingeFit;

namespace
{
  // Increments shaped like P10's at rest (M2, joint 3): lateral forces turn
  // theta and phi alike with some twist, torsion couples mostly psi,
  // in-plane forces phi. Forces in N.
  std::vector<FabricHingeFit::Increment> increments_of(const FabricHinge &hinge)
  {
    const std::vector<std::tuple<std::string, double, Eigen::Vector3d>> shapes = {
      {"lateral", 0.1, {-0.004, -0.015, -0.013}}, {"lateral", 0.3, {-0.026, -0.042, -0.045}},
      {"lateral", 0.5, {-0.075, -0.065, -0.098}}, {"torsion", 0.2, {-0.011, 0.0005, 0.0002}},
      {"torsion", 0.6, {-0.031, 0.0012, -0.0004}}, {"bending", 0.1, {0.001, 0.0, -0.02}},
      {"bending", 0.3, {0.0, 0.0003, -0.06}}};
    std::vector<FabricHingeFit::Increment> increments;
    for (const auto &[role, force, angle] : shapes)
      increments.push_back({role, 0.0, force, angle, hinge.evaluate(angle).torque, false,
                            role == "torsion" ? FabricHingeFit::Increment::Kind::twist :
                            role == "lateral" ? FabricHingeFit::Increment::Kind::lateral :
                                                FabricHingeFit::Increment::Kind::bend});
    return increments;
  }

  // Increments shaped like P10's at 20 kPa (M2, joint 4): a lateral force
  // first twists the joint and turns theta little, then, past the knee,
  // theta and phi together; the torsion samples tilt theta with psi, with
  // no theta torque (not reciprocal: no law holds them, and the fit leaves
  // their theta and phi rows out).
  using Kind = FabricHingeFit::Increment::Kind;
  std::vector<FabricHingeFit::Increment> inflated_increments(const FabricHinge &hinge)
  {
    const std::vector<std::tuple<Kind, double, Eigen::Vector3d>> shapes = {
      {Kind::lateral, 0.1, {-0.010, -0.0005, -0.001}}, {Kind::lateral, 0.3, {-0.034, -0.0066, -0.011}},
      {Kind::lateral, 0.5, {-0.063, -0.033, -0.043}},  {Kind::lateral, 1.0, {-0.115, -0.063, -0.114}},
      {Kind::bend, 0.1, {0.0, 0.0, -0.02}},             {Kind::bend, 0.3, {0.0, 0.0, -0.05}}};
    std::vector<FabricHingeFit::Increment> increments;
    for (const auto &[kind, force, angle] : shapes)
      increments.push_back({"", 2e4, force, angle, hinge.evaluate(angle).torque, false, kind});
    const Eigen::Vector3d tilt(-0.04, 0.004, 0.0);
    increments.push_back({"", 2e4, 0.3, tilt, Eigen::Vector3d(hinge.k[0] * tilt[0], 0.0, 0.0), false, Kind::twist});
    return increments;
  }

  // The rules of an inflated law (FabricHingeFit::Constraints) for
  // `increments`, with `hinge`'s in-plane tangent to keep.
  FabricHingeFit::Constraints inflated_constraints(const std::vector<FabricHingeFit::Increment> &increments,
                                                   const FabricHinge &hinge)
  {
    FabricHingeFit::Constraints c;
    c.inflated  = true;
    c.in_plane  = hinge.evaluate(Eigen::Vector3d::Zero()).tangent(2, 2);
    c.knee_low  = std::numeric_limits<double>::infinity();
    for (const auto &in : increments)
      if (in.kind == Kind::lateral)
        {
          c.knee_low  = std::min(c.knee_low, std::abs(in.torque[1]));
          c.knee_high = std::max(c.knee_high, std::abs(in.torque[1]));
        }
    return c;
  }
} // namespace

TEST_CASE("an inflated finger's pre-stressed layer is recovered from the samples it made")
{
  // On the grid: r = 0.85, theta_0 = max|d theta| / 2^4 (0.063 / 16), give
  // 2^3. The fit holds the in-plane tangent and leaves the torsion sample's
  // theta and phi rows out (its theta turns with psi without a torque,
  // which would otherwise pull the fit off the law); exact up to the normal
  // equations' round-off, as above.
  FabricHinge made;
  made.k          = Eigen::Vector3d(0.12, 0.45, 0.05);
  made.kappa      = 5.3;
  made.r          = 0.85;
  made.theta_0    = 0.063 / 16;
  made.layer_give = 8.0;
  const auto          increments = inflated_increments(made);
  FabricHingeFit::Fit fit;
  REQUIRE(FabricHingeFit::fit(increments, fit, inflated_constraints(increments, made)));
  CHECK((fit.hinge.k - made.k).cwiseAbs().maxCoeff() < 1e-8 * made.k.maxCoeff());
  CHECK(fit.hinge.kappa == Approx(made.kappa).epsilon(1e-8));
  CHECK(fit.hinge.r == Approx(made.r).epsilon(1e-12));
  CHECK(fit.hinge.theta_0 == Approx(made.theta_0).epsilon(1e-12));
  CHECK(fit.hinge.layer_give == made.layer_give);
  CHECK(fit.relative_residual < 1e-7);
  // Its knee lies among the lateral samples: stiff under the lightest,
  // soft under the heaviest.
  const double knee = 2 * made.kappa * made.theta_0;
  CHECK(std::abs(increments[0].torque[1]) < knee);
  CHECK(std::abs(increments[3].torque[1]) > knee);
}

TEST_CASE("inflated samples that a linear spring holds get no law")
{
  // Lateral samples that never pass a knee (P10 at 40 and 50 kPa): no
  // pre-stressed layer halves the springs' residual with its knee among
  // them, and the chain keeps its own linear springs there.
  FabricHinge springs;
  springs.k               = Eigen::Vector3d(0.12, 2.5, 0.2);
  const auto increments   = inflated_increments(springs);
  FabricHingeFit::Fit fit;
  CHECK_FALSE(FabricHingeFit::fit(increments, fit, inflated_constraints(increments, springs)));
  // At rest the same samples give the springs back.
  REQUIRE(FabricHingeFit::fit(increments, fit));
  CHECK(fit.hinge.kappa == 0.0);
  CHECK(fit.hinge.k[1] == Approx(springs.k[1]).epsilon(1e-10));
}

TEST_CASE("a fabric hinge is recovered from the samples it made")
{
  // The grid holds r = 0.3 and theta_0 = max|d theta| / 2 (the lateral
  // samples' 0.065 / 2): the fit is exact up to the normal equations'
  // round-off, cond(N) eps ~ 1e-10 here.
  for (const double theta_0 : {0.0, 0.0325})
    {
      FabricHinge made;
      made.k       = Eigen::Vector3d(0.086, 0.052, 0.146);
      made.kappa   = 0.58;
      made.r       = 0.3;
      made.theta_0 = theta_0;
      FabricHingeFit::Fit fit;
      REQUIRE(FabricHingeFit::fit(increments_of(made), fit));
      CHECK((fit.hinge.k - made.k).cwiseAbs().maxCoeff() < 1e-8 * made.k.maxCoeff());
      CHECK(fit.hinge.kappa == Approx(made.kappa).epsilon(1e-8));
      CHECK(fit.hinge.r == Approx(made.r).epsilon(1e-12));
      CHECK(fit.hinge.theta_0 == Approx(theta_0).margin(1e-15));
      CHECK(fit.relative_residual < 1e-7);
      CHECK(fit.n_samples == 7);
    }
}

TEST_CASE("linear springs are fitted as linear springs")
{
  FabricHinge springs;
  springs.k = Eigen::Vector3d(0.09, 0.4, 0.2);
  FabricHingeFit::Fit fit;
  REQUIRE(FabricHingeFit::fit(increments_of(springs), fit));
  CHECK(fit.hinge.kappa == 0.0); // no fibre candidate beats the springs by more than round-off
  CHECK((fit.hinge.k - springs.k).cwiseAbs().maxCoeff() < 1e-10 * springs.k.maxCoeff());
}

TEST_CASE("samples past a limit point and below the threshold are left out")
{
  FabricHinge springs;
  springs.k = Eigen::Vector3d(0.09, 0.4, 0.2);
  auto all  = increments_of(springs);
  // A heavier lateral force that turns the joint less (sideways buckling
  // moved the bending elsewhere), and one even heavier: both dropped.
  all.push_back({"lateral", 0.0, 0.7, {-0.05, -0.05, -0.07}, springs.evaluate({-0.05, -0.05, -0.07}).torque});
  all.push_back({"lateral", 0.0, 1.0, {-0.2, -0.2, -0.3}, springs.evaluate({-0.2, -0.2, -0.3}).torque});
  // A torsion sample turning the joint by less than the threshold.
  all.push_back({"torsion", 0.0, 0.05, {-0.0005, 0.0, 0.0}, springs.evaluate({-0.0005, 0.0, 0.0}).torque});
  int        n_past_limit = 0;
  const auto kept         = FabricHingeFit::usable(all, 1e-3, n_past_limit);
  CHECK(kept.size() == 7);
  CHECK(n_past_limit == 2);
  // A heavier bending force that turns the joint more, but that the FEM
  // followed past a limit point of its forces (displacement control): it
  // lies on the buckled branch, and is left out with those heavier.
  auto buckled = increments_of(springs);
  buckled.push_back({"bending", 0.0, 0.9, {0.0, 0.3, 0.0}, springs.evaluate({0.0, 0.3, 0.0}).torque, true});
  buckled.push_back({"bending", 0.0, 1.2, {0.0, 0.4, 0.0}, springs.evaluate({0.0, 0.4, 0.0}).torque});
  int past = 0;
  CHECK(FabricHingeFit::usable(buckled, 1e-3, past).size() == 7);
  CHECK(past == 2);
  // A joint turning against its torque has no positive fit.
  std::vector<FabricHingeFit::Increment> against = {
    {"lateral", 0.0, 0.1, {0.01, 0.01, 0.0}, {-0.001, -0.001, 0.0}}};
  FabricHingeFit::Fit fit;
  CHECK_FALSE(FabricHingeFit::fit(against, fit));
}
