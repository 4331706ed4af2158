// The chain with a JointForceLaw: its residual is the energy's gradient and
// its tangent the residual's (central differences) with the fabric hinges
// blended in pressure; the pressure-only state is unchanged by the law; a
// law is completed with the linear springs at pressures it was not fitted
// at, except between two of its laws where no force sample was made; from
// rest theta blends in series (the infimal convolution against a brute-force
// minimum, its torque and tangent against central differences, the springs'
// harmonic mean), between inflated laws in parallel; and the joint-law file
// is read, or rejected naming its row.
#include <softchain/chain/chain_equilibrium.h>
#include <softchain/chain/joint_force_law.h>
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/input_error.h>

#include "../data/scratch_directory.h"
#include "central_differences.h"
#include "reduction_output.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace softchain::chain;
using softchain::data::FabricHinge;

namespace
{
  constexpr int    n_joints = 5;
  constexpr double a        = 0.01;

  FabricHinge hinge(double scale, double theta_0)
  {
    FabricHinge h;
    h.k       = scale * Eigen::Vector3d(0.03, 0.01, 0.02);
    h.kappa   = scale * 0.05;
    h.r       = 0.3;
    h.theta_0 = theta_0;
    return h;
  }

  // Every joint: the hinge at rest at 0 and a stiffer, pre-stretched one at 40 kPa.
  ChainModel finger_with_law()
  {
    ChainModel                        model = testing::uniform_finger(n_joints, a, Eigen::Vector3d(0.03, 0.01, 0.02),
                                                                      Eigen::Vector3d(0.01, -0.02, 0.05) * 1e-6);
    std::vector<JointForceLaw::Table> tables(n_joints, {{0.0, 4e4}, {hinge(1, 0), hinge(2, 0.01)}});
    model.set_force_law(JointForceLaw(tables));
    return model;
  }

  // The blend from rest by brute force: (1 - w) W_lo(x) + w W_hi(y) over a
  // fine scan of x (theta of the law at rest; y = (d_theta - (1 - w) x) / w),
  // refined by golden sections, independently of JointForceLaw's Newton.
  double series_energy(const FabricHinge &lo, const FabricHinge &hi, double w, const Eigen::Vector3d &d)
  {
    const auto F = [&](double x) {
      Eigen::Vector3d at_lo = d, at_hi = d;
      at_lo(1)              = x;
      at_hi(1)              = (d(1) - (1 - w) * x) / w;
      return (1 - w) * lo.evaluate(at_lo).energy + w * hi.evaluate(at_hi).energy;
    };
    const double span = 0.2;
    double       best = d(1), lowest = F(best);
    for (int i = -1000; i <= 1000; ++i)
      if (const double x = d(1) + span * i / 1000, f = F(x); f < lowest)
        best = x, lowest = f;
    double       left = best - span / 1000, right = best + span / 1000;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    for (int i = 0; i < 200; ++i)
      {
        const double x1 = right - golden * (right - left), x2 = left + golden * (right - left);
        if (F(x1) < F(x2))
          right = x2;
        else
          left = x1;
      }
    return F(0.5 * (left + right));
  }

  Eigen::VectorXd angles(double amplitude)
  {
    Eigen::VectorXd q(3 * n_joints);
    for (int j = 0; j < q.size(); ++j)
      q[j] = amplitude * std::sin(2.3 * j + 1.0);
    return q;
  }
} // namespace

TEST_CASE("with a force law the residual is the energy's gradient and the tangent its derivative")
{
  // The hinges' energy is piecewise quadratic in the angles and the chain's
  // kinematics smooth: central differences err by h^2/6 |r'''| + eps |r| /
  // h as in chain_equilibrium_test (1e-8 of the largest entry at h = 1e-5),
  // unless a fibre's kink lies within h of q (none does at these angles).
  const ChainModel model = finger_with_law();
  ChainEquilibrium solver(model);
  solver.set_load({1e4, {{{0.045, 0.002, -0.001}, {0.05, -0.2, 0.1}}}}); // a quarter of the way
  const Eigen::VectorXd q        = angles(0.2);
  const Eigen::VectorXd residual = solver.residual(q);
  CHECK((testing::energy_gradient(solver, q, 1e-5) - residual).cwiseAbs().maxCoeff() <
        1e-8 * residual.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd tangent = solver.tangent(q);
  CHECK((tangent - testing::central_differences(solver, q, 1e-5)).cwiseAbs().maxCoeff() <
        1e-8 * tangent.cwiseAbs().maxCoeff());
  // The fibres couple theta and phi of a joint: the law is in H.
  CHECK(std::abs(tangent(1, 2)) > 1e-3 * tangent.cwiseAbs().maxCoeff());
}

TEST_CASE("the law leaves the pressure-only state and turns the joints along it under forces")
{
  const ChainModel law    = finger_with_law();
  const ChainModel linear = law.with_linear_joints();
  ChainEquilibrium with_law(law), without(linear);
  const Equilibrium inflated = with_law.solve({3e4, {}});
  REQUIRE(inflated.converged);
  CHECK((inflated.angles - without.solve({3e4, {}}).angles).cwiseAbs().maxCoeff() < 1e-15);
  // A lateral tip force at rest: every joint takes the hinge's torque
  // increment, T(d) = Q, and the taut edge turns phi too (the law's
  // coupling; the linear springs keep phi at 0).
  const ChainLoad   lateral{0.0, {{{n_joints * a, 0.0, 0.0}, {0.0, 0.0, 0.02}}}};
  const Equilibrium bent = with_law.solve(lateral);
  REQUIRE(bent.converged);
  CHECK(std::abs(bent.angles[3 * (n_joints - 1) + 2]) > 0.1 * std::abs(bent.angles[3 * (n_joints - 1) + 1]));
  CHECK(std::abs(without.solve(lateral).angles[3 * (n_joints - 1) + 2]) < 1e-12);
}

TEST_CASE("a law without fibres is the linear springs it holds")
{
  // At a pressure where neither end of the blend has fibres the chain takes
  // its fast path, J_p p + k (q - q_p), which is k q where k is the model's
  // own stiffness (k q_p = J_p p): the residual and the tangent of the
  // linear chain, up to round-off.
  ChainModel        model = testing::uniform_finger(n_joints, a, Eigen::Vector3d(0.03, 0.01, 0.02),
                                                    Eigen::Vector3d(0.01, -0.02, 0.05) * 1e-6);
  FabricHinge       springs;
  springs.k = Eigen::Vector3d(0.03, 0.01, 0.02);
  model.set_force_law(JointForceLaw(std::vector<JointForceLaw::Table>(n_joints, {{0.0}, {springs}})));
  const ChainModel  linear = model.with_linear_joints();
  ChainEquilibrium  with_law(model), without(linear);
  const ChainLoad   load{3e4, {{{0.045, 0.002, -0.001}, {0.05, -0.2, 0.1}}}};
  with_law.set_load(load);
  without.set_load(load);
  const Eigen::VectorXd q = angles(0.2);
  const Eigen::VectorXd r = without.residual(q);
  CHECK((with_law.residual(q) - r).cwiseAbs().maxCoeff() < 1e-14 * r.cwiseAbs().maxCoeff());
  CHECK((with_law.tangent(q) - without.tangent(q)).cwiseAbs().maxCoeff() < 1e-14);
}

TEST_CASE("a law is completed with the linear springs at the pressures it lacks")
{
  // Joint 1 has a law at 0 only; the springs' k(p) tables hold 0 and 8e4.
  JointStiffness springs(std::vector<Eigen::Vector3d>(2, Eigen::Vector3d(1, 2, 3)));
  springs.set_in_pressure(2, {PiecewiseLinear({0.0, 8e4}, {3.0, 6.0}), PiecewiseLinear({0.0, 8e4}, {3.0, 6.0})});
  const JointForceLaw complete = JointForceLaw({{{0.0}, {hinge(1, 0)}}, {}}).completed_with(springs);
  REQUIRE(complete.table(0).pressures == std::vector<double>{0.0, 8e4});
  REQUIRE(complete.table(1).pressures == std::vector<double>{0.0, 8e4});
  CHECK(complete.table(0).hinges[0].kappa == hinge(1, 0).kappa);
  CHECK(complete.table(0).hinges[1].kappa == 0.0);
  CHECK(complete.table(0).hinges[1].k == Eigen::Vector3d(1, 2, 6));
  // Half way in pressure from rest, the series blend of the two laws (the
  // brute-force minimum is exact to round-off in its energy: 1e-12).
  const Eigen::Vector3d d(0.01, 0.02, -0.01);
  FabricHinge           springs_8e4;
  springs_8e4.k = Eigen::Vector3d(1, 2, 6);
  const double expected = series_energy(hinge(1, 0), springs_8e4, 0.5, d);
  CHECK(complete.at(4e4, 0).evaluate(d).energy == Approx(expected).epsilon(1e-12));
}

TEST_CASE("between two laws, at a pressure without force samples, the laws blend")
{
  // Laws at 0 and 4e4; the springs' k_phi(p) (pressure samples) holds 2e4,
  // their k_theta(p) (force samples) 0, 4e4 and 8e4. At 2e4 no linear knot
  // is put between the laws (the finger there is neither's, and the linear
  // springs of the lightest forces would replace both); at 8e4, beyond the
  // last law, the springs hold as before.
  JointStiffness springs(std::vector<Eigen::Vector3d>(1, Eigen::Vector3d(1, 2, 3)));
  springs.set_in_pressure(2, {PiecewiseLinear({2e4}, {3.0})});
  springs.set_in_pressure(1, {PiecewiseLinear({0.0, 4e4, 8e4}, {2.0, 2.5, 3.0})});
  const JointForceLaw complete = JointForceLaw({{{0.0, 4e4}, {hinge(1, 0), hinge(2, 0.01)}}}).completed_with(springs);
  REQUIRE(complete.table(0).pressures == std::vector<double>{0.0, 4e4, 8e4});
  const Eigen::Vector3d d(0.01, 0.02, -0.01);
  CHECK(complete.at(2e4, 0).evaluate(d).energy ==
        Approx(series_energy(hinge(1, 0), hinge(2, 0.01), 0.5, d)).epsilon(1e-12));
  // Between two inflated laws (4e4 and the springs at 8e4) they blend in
  // parallel: half of each law's torque.
  const Eigen::Vector3d expected = 0.5 * (hinge(2, 0.01).evaluate(d).torque + Eigen::Vector3d(1, 3, 3).cwiseProduct(d));
  CHECK((complete.at(6e4, 0).evaluate(d).torque - expected).norm() < 1e-15 * expected.norm());
  // A pressure of force samples where no law was fitted stays a knot.
  springs.set_in_pressure(1, {PiecewiseLinear({0.0, 2e4, 4e4}, {2.0, 2.2, 2.5})});
  const JointForceLaw with_samples =
    JointForceLaw({{{0.0, 4e4}, {hinge(1, 0), hinge(2, 0.01)}}}).completed_with(springs);
  REQUIRE(with_samples.table(0).pressures == std::vector<double>{0.0, 2e4, 4e4});
  CHECK(with_samples.table(0).hinges[1].kappa == 0.0);
}

TEST_CASE("from rest theta blends in series: its compliance, not its stiffness, interpolates in pressure")
{
  const double w = 0.3; // 1.2e4 between the laws at 0 and 4e4
  SECTION("linear springs: the harmonic mean for theta, the arithmetic one for psi and phi")
  {
    FabricHinge rest, inflated, further;
    rest.k     = Eigen::Vector3d(1, 2, 3);
    inflated.k = Eigen::Vector3d(3, 8, 5);
    further.k  = Eigen::Vector3d(4, 10, 7);
    const JointForceLaw law({{{0.0, 4e4, 8e4}, {rest, inflated, further}}});
    const auto          blend = law.at(w * 4e4, 0);
    REQUIRE(blend.springs);
    CHECK((*blend.springs - Eigen::Vector3d(0.7 * 1 + 0.3 * 3, 1 / (0.7 / 2 + 0.3 / 8), 0.7 * 3 + 0.3 * 5)).norm() <
          1e-15);
    const auto inflated_blend = law.at(6e4, 0);
    REQUIRE(inflated_blend.springs);
    CHECK((*inflated_blend.springs - Eigen::Vector3d(3.5, 9, 6)).norm() < 1e-15);
  }
  SECTION("fabric hinges: the infimal convolution, its torque and tangent")
  {
    const JointForceLaw law({{{0.0, 4e4}, {hinge(1, 0), hinge(2, 0.01)}}});
    const auto          blend = law.at(w * 4e4, 0);
    REQUIRE_FALSE(blend.springs);
    // Increments with both fibres taut, one slack, and a lateral turn past
    // the pre-stretched law's knee.
    for (const Eigen::Vector3d &d : {Eigen::Vector3d(0.01, 0.002, -0.01), Eigen::Vector3d(0.01, 0.02, -0.01),
                                    Eigen::Vector3d(-0.02, -0.05, 0.03)})
      {
        INFO("d = " << d.transpose());
        const FabricHinge::Value v = blend.evaluate(d);
        CHECK(v.energy == Approx(series_energy(hinge(1, 0), hinge(2, 0.01), w, d)).epsilon(1e-12));
        // Central differences of a piecewise quadratic energy (its kinks
        // farther than h from these d): round-off eps |W| / h, 1e-9 of |T|.
        const double h = 1e-6;
        for (int a = 0; a < 3; ++a)
          {
            const Eigen::Vector3d    e     = h * Eigen::Vector3d::Unit(a);
            const FabricHinge::Value plus  = blend.evaluate(d + e), minus = blend.evaluate(d - e);
            const double             torque = (plus.energy - minus.energy) / (2 * h);
            CHECK(std::abs(v.torque(a) - torque) < 1e-9 * v.torque.norm());
            const Eigen::Vector3d column = (plus.torque - minus.torque) / (2 * h);
            CHECK((v.tangent.col(a) - column).norm() < 1e-8 * v.tangent.norm());
          }
        // The laws are in series in theta: the law at rest is the softer
        // sideways, so the blend is softer than the parallel one.
        const Eigen::Matrix3d parallel = (1 - w) * hinge(1, 0).evaluate(d).tangent + w * hinge(2, 0.01).evaluate(d).tangent;
        CHECK(v.tangent(1, 1) < parallel(1, 1));
      }
  }
  SECTION("laws free in theta (no theta spring, both fibres slack) leave a finite law")
  {
    FabricHinge free = hinge(1, 0);
    free.k(1)        = 0.0;
    const JointForceLaw      law({{{0.0, 4e4}, {free, free}}});
    const Eigen::Vector3d    d(0.01, 0.0, -0.01); // e_u = r d_phi < 0: both edges slack
    const FabricHinge::Value v = law.at(w * 4e4, 0).evaluate(d), exact = free.evaluate(d);
    REQUIRE(exact.tangent(1, 1) == 0.0);
    CHECK(v.tangent.allFinite());
    CHECK((v.tangent - exact.tangent).norm() < 1e-15 * exact.tangent.norm());
    CHECK((v.torque - exact.torque).norm() < 1e-15 * exact.torque.norm());
  }
  SECTION("a law in series with itself is that law")
  {
    const JointForceLaw      law({{{0.0, 4e4}, {hinge(2, 0.01), hinge(2, 0.01)}}});
    const Eigen::Vector3d    d(0.01, 0.02, -0.01);
    const FabricHinge::Value v = law.at(w * 4e4, 0).evaluate(d), exact = hinge(2, 0.01).evaluate(d);
    CHECK(std::abs(v.energy - exact.energy) < 1e-15 * std::abs(exact.energy));
    CHECK((v.torque - exact.torque).norm() < 1e-15 * exact.torque.norm());
    CHECK((v.tangent - exact.tangent).norm() < 1e-14 * exact.tangent.norm());
  }
}

TEST_CASE("the joint-law file gives the chain its law, and bad rows are input errors naming the row")
{
  softchain::testing::ScratchDirectory dir("chain_joint_law");
  const StiffnessFiles files(dir.path().string(), softchain::data::RotationMethod::affine_fit, 0.5);
  const testing::UniformReduction r;
  testing::write_reduction(files, r);
  const Eigen::Vector3d tip(r.n * r.a, 0, 0);
  CHECK(files.read_model("M2", tip, StiffnessColumn::value, true).force_law() == nullptr);
  const auto write_law = [&](const std::string &extra_row) {
    std::ofstream out(files.joint_law_path());
    out << "pressure,joint,k_psi,k_theta,k_phi,kappa,r,theta_0,samples,relative_residual\n"
        << "0,2,0.03,0.01,0.02,0.05,0.3,0,9,0.04\n"
        << extra_row;
  };
  write_law("");
  const ChainModel model = files.read_model("M2", tip, StiffnessColumn::value, true);
  REQUIRE(model.force_law() != nullptr);
  CHECK(model.force_law()->table(1).hinges.front().kappa == 0.05);
  CHECK_FALSE(model.force_law()->table(0).hinges.front().kappa > 0); // joint 1: the linear springs
  CHECK(files.read_model("M2", tip, StiffnessColumn::value, false).force_law() == nullptr);
  write_law("0,3,0.03,-0.01,0.02,0.05,0.3,0,9,0.04\n");
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains("_joint_law.csv, row 2") && Catch::Contains("must be positive"));
  write_law("0,2,0.03,0.01,0.02,0.05,0.3,0,9,0.04\n");
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains("row 2") && Catch::Contains("listed twice for joint 2"));
  // The layer's give (a later column; files without it have none).
  const auto write_given = [&](const std::string &give) {
    std::ofstream out(files.joint_law_path());
    out << "pressure,joint,k_psi,k_theta,k_phi,kappa,r,theta_0,layer_give,samples,relative_residual\n"
        << "2e4,2,0.03,0.5,0.02,4,0.8,0.002," << give << ",11,0.08\n";
  };
  write_given("8");
  CHECK(files.read_model("M2", tip, StiffnessColumn::value, true).force_law()->table(1).hinges.front().layer_give == 8.0);
  write_given("-1");
  CHECK_THROWS_WITH(files.read_model("M2", tip, StiffnessColumn::value, true),
                    Catch::Contains("row 1") && Catch::Contains("layer_give not negative"));
}
