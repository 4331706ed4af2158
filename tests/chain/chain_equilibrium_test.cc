// Equilibrium of the chain against closed forms: uniform moment, linear
// small-load solution, decoupled torsion and lateral bending, joint-by-joint
// moment balance at large deflection, the exact tangent against finite
// differences, and loads that the chain cannot equilibrate.
#include <softchain/chain/chain_equilibrium.h>

#include "central_differences.h"
#include "uniform_finger.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
using softchain::chain::testing::uniform_finger;

namespace
{
  constexpr int    n_joints = 9;
  constexpr double a        = 0.01;  // m, the paper's joint spacing
  constexpr double length   = 0.09;  // m, tip at n a
  constexpr double k        = 0.05;  // N m / rad, the order of the paper's k_phi

  // Moment of the point loads distal to joint i about its current centre.
  Eigen::Vector3d distal_moment(const ChainPose &pose, const ChainLoad &load,
                                const KinematicChain &chain, int i)
  {
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (const PointLoad &p : load.point_loads)
      {
        const int link = chain.link_of(p.reference_point);
        if (link >= i)
          moment += (chain.point_position(pose, link, p.reference_point) -
                     pose.joint_positions[i]).cross(p.force);
      }
    return moment;
  }

  PointLoad tip_force(const Eigen::Vector3d &force, const Eigen::Vector3d &offset = Eigen::Vector3d::Zero())
  {
    return {Eigen::Vector3d(length, 0, 0) + offset, force};
  }
} // namespace

TEST_CASE("a uniform moment bends a uniform chain into equal angles phi = tau / k, past 180 deg")
{
  for (const double degrees : {10.0, 25.0, 35.0}) // 90, 225 and 315 deg in total
    {
      const double     tau   = k * degrees * M_PI / 180.0; // N m per joint
      const double     p     = 5e4;                         // Pa
      const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(4 * k, k, k),
                                              Eigen::Vector3d(0, 0, tau / p));
      ChainEquilibrium  solver(model);
      const Equilibrium e = solver.solve({p, {}});
      REQUIRE(e.converged);
      CHECK(e.residual <= 1e-10);
      CHECK(e.iterations == 0); // the solve starts at K^-1 J_p p, the answer
      for (int i = 0; i < n_joints; ++i)
        {
          // The equations are linear here: round-off of one LLT solve.
          CHECK(e.angles[3 * i + 2] == Approx(tau / k).epsilon(1e-12));
          CHECK(std::abs(e.angles[3 * i]) + std::abs(e.angles[3 * i + 1]) < 1e-14);
        }
    }
}

TEST_CASE("a small tip force gives the linear cantilever chain solution")
{
  // Linear: k_phi phi_i = f_y (L - x_i), x_i = (i + 1/2) a. The force is
  // chosen so that the total rotation is about 1e-4 rad: the geometric
  // nonlinearity is second order, relative 1e-8 < 1e-6.
  const ChainModel model  = uniform_finger(n_joints, a, Eigen::Vector3d(4 * k, k, k));
  const double     fy     = 1e-4 * k / (n_joints * length);
  ChainEquilibrium solver(model);
  const Equilibrium e = solver.solve({0.0, {tip_force({0, fy, 0})}});
  REQUIRE(e.converged);
  for (int i = 0; i < n_joints; ++i)
    {
      const double linear = fy * (length - (i + 0.5) * a) / k;
      CHECK(e.angles[3 * i + 2] == Approx(linear).epsilon(1e-6));
      CHECK(std::abs(e.angles[3 * i]) + std::abs(e.angles[3 * i + 1]) < 1e-12 * std::abs(linear));
    }
}

TEST_CASE("torsion-only and lateral-only loads stay decoupled with diagonal K")
{
  const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(4 * k, k, 2 * k));
  ChainEquilibrium solver(model);
  SECTION("a couple about the finger axis twists it only")
  {
    // +-f_z at (L, +-d, 0): the couple 2 d f cos(Psi) e_x for a total twist
    // Psi, so k_psi psi_i = 2 d f cos(n psi_i) at every joint.
    const double    d = 0.005, f = 2.0;
    const ChainLoad load{0.0, {tip_force({0, 0, f}, {0, d, 0}), tip_force({0, 0, -f}, {0, -d, 0})}};
    const Equilibrium e = solver.solve(load);
    REQUIRE(e.converged);
    const double psi = e.angles[0];
    CHECK(psi > 0.05); // a large twist, about 40 deg in total
    for (int i = 0; i < n_joints; ++i)
      {
        CHECK(4 * k * e.angles[3 * i] == Approx(2 * d * f * std::cos(n_joints * psi)).epsilon(1e-9));
        CHECK(std::abs(e.angles[3 * i + 1]) + std::abs(e.angles[3 * i + 2]) < 1e-12);
      }
  }
  SECTION("a sideways tip force bends it laterally only, balancing moments at every joint")
  {
    const ChainLoad   load{0.0, {tip_force({0, 0, 1.0})}}; // ~ 60 deg lateral tip rotation
    const Equilibrium e = solver.solve(load);
    REQUIRE(e.converged);
    const ChainPose &pose = solver.pose();
    for (int i = 0; i < n_joints; ++i)
      {
        // In the x-z plane the theta axis stays e_y: k theta_i = M_i . e_y.
        const double moment = distal_moment(pose, load, model.chain(), i).y();
        CHECK(k * e.angles[3 * i + 1] == Approx(moment).epsilon(1e-9));
        CHECK(std::abs(e.angles[3 * i]) + std::abs(e.angles[3 * i + 2]) < 1e-12);
      }
  }
}

TEST_CASE("pressure with a tip force past 180 deg balances the moment at every joint")
{
  // The moment balance k phi_i = tau_p + (M_i)_z in the x-y plane uses only
  // forward kinematics, independent of the Newton tangent; 1e-9 relative is
  // the solver tolerance 1e-10 with a margin for the scale of the residual.
  const double     tau   = k * 0.4; // 0.4 rad per joint without the force: 206 deg
  const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(4 * k, k, k),
                                          Eigen::Vector3d(0, 0, tau));
  ChainEquilibrium  solver(model);
  const ChainLoad   load{1.0, {tip_force({0.03, -0.04, 0})}};
  const Equilibrium e = solver.solve(load);
  REQUIRE(e.converged);
  CHECK(e.angles.sum() > M_PI);
  for (int i = 0; i < n_joints; ++i)
    {
      const double moment = distal_moment(solver.pose(), load, model.chain(), i).z();
      CHECK(k * e.angles[3 * i + 2] == Approx(tau + moment).epsilon(1e-9));
    }
}

TEST_CASE("the exact tangent matches central differences of the residual")
{
  // Soft joints (k = 0.01) under forces of 1 N at 3-9 cm so that dQ/dq, not
  // K, dominates H. Central differences err by h^2/6 |r'''| + eps |r| / h;
  // with |r'''| ~ |H| (each derivative of a rotation is O(1) per rad) and
  // h = 1e-5: 2e-11 |H| + 1e-11 |H|, bounded by 1e-8 |H|.
  const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(0.03, 0.01, 0.02),
                                          Eigen::Vector3d(0.01, -0.02, 0.05));
  ChainEquilibrium solver(model);
  solver.set_load({0.5,
                   {{{0.035, 0.002, -0.001}, {0.2, -1.0, 0.3}},
                    {{0.09, 0.0, 0.004}, {-0.5, 0.1, 0.8}},
                    {{0.062, -0.003, 0.0}, {0.0, 0.7, -0.6}}}});
  Eigen::VectorXd q(3 * n_joints);
  for (int j = 0; j < q.size(); ++j)
    q[j] = 0.4 * std::sin(2.3 * j + 1.0);
  const Eigen::MatrixXd tangent    = solver.tangent(q);
  const Eigen::MatrixXd difference = testing::central_differences(solver, q, 1e-5);
  const double          scale      = tangent.cwiseAbs().maxCoeff();
  CHECK((tangent - difference).cwiseAbs().maxCoeff() < 1e-8 * scale);
  // The load part of H is what is being checked: it must be significant.
  CHECK((tangent - Eigen::MatrixXd(Eigen::VectorXd::Constant(q.size(), 0.03).asDiagonal()))
          .cwiseAbs()
          .maxCoeff() > 0.1 * scale);
}

TEST_CASE("the O(n) Newton step solves the dense tangent system")
{
  // Same loaded state as above; the dense LLT solve of the assembled H is the
  // reference. Both are backward stable: relative difference ~ cond(H) eps,
  // cond(H) < 1e3 here, so 1e-11.
  const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(0.3, 0.1, 0.2));
  ChainEquilibrium solver(model);
  solver.set_load({0.0, {{{0.035, 0.002, -0.001}, {0.02, -0.1, 0.03}}, {{0.09, 0.0, 0.004}, {-0.05, 0.01, 0.08}}}});
  Eigen::VectorXd q(3 * n_joints);
  for (int j = 0; j < q.size(); ++j)
    q[j] = 0.1 * std::sin(2.3 * j + 1.0);
  const Eigen::MatrixXd tangent = solver.tangent(q);
  const Eigen::VectorXd residual = solver.residual(q);
  REQUIRE(tangent.llt().info() == Eigen::Success); // positive definite: no shift
  const Eigen::VectorXd dense = -tangent.llt().solve(residual);
  REQUIRE(dense.lpNorm<Eigen::Infinity>() < 1.5); // below the step cap
  const Eigen::VectorXd step = solver.newton_step(q);
  CHECK((step - dense).norm() < 1e-11 * dense.norm());
}

TEST_CASE("the residual is the gradient of the energy")
{
  // Same error model as the tangent check, one derivative lower.
  const ChainModel model = uniform_finger(4, a, Eigen::Vector3d(0.03, 0.01, 0.02),
                                          Eigen::Vector3d(0.01, -0.02, 0.05));
  ChainEquilibrium solver(model);
  solver.set_load({0.5, {{{0.04, 0.001, 0.0}, {0.3, -1.0, 0.5}}}});
  Eigen::VectorXd q(12);
  for (int j = 0; j < q.size(); ++j)
    q[j] = 0.5 * std::cos(1.3 * j);
  const Eigen::VectorXd residual = solver.residual(q);
  CHECK((testing::energy_gradient(solver, q, 1e-5) - residual).cwiseAbs().maxCoeff() <
        1e-8 * residual.cwiseAbs().maxCoeff());
}

TEST_CASE("a load the chain cannot equilibrate is a failure with its reason, not a pose")
{
  const ChainModel model = uniform_finger(n_joints, a, Eigen::Vector3d(4 * k, k, k),
                                          Eigen::Vector3d(0, 0, 1.0));
  SECTION("an equilibrium beyond half a turn per joint is outside the chain's range")
  {
    ChainEquilibrium  solver(model);
    const Equilibrium e = solver.solve({k * 4.0, {}}); // phi = 4 rad per joint
    CHECK_FALSE(e.converged);
    CHECK_THAT(e.failure, Catch::Contains("joint 1: phi") && Catch::Contains("outside"));
  }
  SECTION("a straight finger under an axial load beyond buckling is unstable, not an answer")
  {
    // Critical load of the chain ~ pi^2 k a / (4 L^2) = 0.15 N; 5 N compresses it far beyond.
    ChainEquilibrium  solver(model);
    const Equilibrium e = solver.solve({0.0, {tip_force({-5.0, 0.0, 0.0})}});
    CHECK(e.iterations == 0); // the straight pose balances the load exactly
    CHECK_FALSE(e.converged);
    CHECK_THAT(e.failure, Catch::Contains("unstable"));
    // With a small side force the finger buckles into a stable pose.
    const Equilibrium buckled = solver.solve({0.0, {tip_force({-5.0, 0.01, 0.0})}});
    CHECK(buckled.converged);
    CHECK(solver.pose().tip_position.x() < 0.05); // folded back far from x = L
  }
  SECTION("a large load without enough Newton iterations is reported as such")
  {
    EquilibriumSettings settings;
    settings.max_iterations = 2;
    ChainEquilibrium  solver(model, settings);
    const Equilibrium e = solver.solve({0.0, {tip_force({-3.0, 2.0, 0.0})}});
    CHECK_FALSE(e.converged);
    CHECK(e.iterations == 2);
    CHECK(e.residual > 1e-10);
    CHECK_THAT(e.failure, Catch::Contains("no equilibrium within 2 Newton iterations"));
  }
}
