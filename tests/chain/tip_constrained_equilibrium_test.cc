// TipConstrainedEquilibrium and base_wrench against closed forms: a single
// joint and a two-link planar chain with the tip held by a point contact,
// and the free equilibrium recovered when the contact holds the tip where
// the finger would be anyway.
#include <softchain/chain/base_wrench.h>
#include <softchain/chain/tip_constrained_equilibrium.h>

#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace softchain::chain;
using softchain::chain::testing::uniform_finger;

namespace
{
  // Joint angles (psi, theta, phi) per joint, phi_i given, the others 0.
  Eigen::VectorXd planar_angles(const std::vector<double> &phi)
  {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * phi.size());
    for (std::size_t i = 0; i < phi.size(); ++i)
      q(3 * i + 2) = phi[i];
    return q;
  }

  // The solver converges to a relative residual of 1e-10 (EquilibriumSettings);
  // with condition numbers of the 2x2 statics below ~10, 1e-8 bounds the
  // errors of angles [rad] and relative forces with a 10x margin.
  constexpr double tolerance = 1e-8;
} // namespace

TEST_CASE("two-link planar chain with its tip held: the angles of the inverse kinematics and "
          "the contact force of the statics")
{
  // Joints at x = a/2 and 3a/2, tip at 2a: links of length L1 = a, L2 = a/2;
  // bending stiffness k1 = k2 = k about z, stiff out of the plane.
  const double     a = 0.01, k = 0.02;
  const ChainModel model = uniform_finger(2, a, Eigen::Vector3d(50, 50, k));
  const double     phi1 = 0.4, phi2 = 0.6, L1 = a, L2 = 0.5 * a;
  const Eigen::Vector3d c1(0.5 * a, 0, 0);
  const Eigen::Vector3d c2 = c1 + L1 * Eigen::Vector3d(std::cos(phi1), std::sin(phi1), 0);
  const Eigen::Vector3d tip =
    c2 + L2 * Eigen::Vector3d(std::cos(phi1 + phi2), std::sin(phi1 + phi2), 0);

  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(ChainLoad{}, tip, planar_angles({0.3, 0.5}));
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK((result.angles - planar_angles({phi1, phi2})).lpNorm<Eigen::Infinity>() < tolerance);

  // Statics: k phi_i = ((x_tip - c_i) x f)_z for i = 1, 2: two equations
  // r_x f_y - r_y f_x = k phi for f_x, f_y; no force out of the plane.
  const Eigen::Vector3d r1 = tip - c1, r2 = tip - c2;
  Eigen::Matrix2d       A;
  A << -r1.y(), r1.x(), -r2.y(), r2.x();
  const Eigen::Vector2d f = A.lu().solve(Eigen::Vector2d(k * phi1, k * phi2));
  const double          scale = f.norm();
  CHECK(std::abs(result.contact_force.x() - f.x()) < tolerance * scale);
  CHECK(std::abs(result.contact_force.y() - f.y()) < tolerance * scale);
  CHECK(std::abs(result.contact_force.z()) < tolerance * scale);

  // The base carries the contact force, and about the first joint the moment
  // that its spring holds.
  const Wrench w = base_wrench(model.chain(), solver.pose(),
                               solver.with_contact(ChainLoad{}, result.contact_force), c1);
  CHECK((w.force - result.contact_force).norm() < tolerance * scale);
  CHECK(std::abs(w.moment.z() - k * phi1) < tolerance * k * phi1);
  CHECK(w.moment.head<2>().norm() < tolerance * k * phi1);
}

TEST_CASE("single joint with its tip held on its circle: the angle, the tangential force and the "
          "base moment")
{
  // One rigid link cannot move its tip along itself: the force along the
  // link is undetermined (minimum-norm solve); what the spring holds is not.
  const double     a = 0.02, k = 0.03, phi = 0.5, L = 0.5 * a;
  const ChainModel model = uniform_finger(1, a, Eigen::Vector3d(50, 50, k));
  const Eigen::Vector3d c(0.5 * a, 0, 0);
  const Eigen::Vector3d tip = c + L * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0);

  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(ChainLoad{}, tip, planar_angles({0.4}));
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK((result.angles - planar_angles({phi})).lpNorm<Eigen::Infinity>() < tolerance);
  const Eigen::Vector3d tangent(-std::sin(phi), std::cos(phi), 0);
  CHECK(std::abs(result.contact_force.dot(tangent) - k * phi / L) < tolerance * k * phi / L);
  const Wrench w = base_wrench(model.chain(), solver.pose(),
                               solver.with_contact(ChainLoad{}, result.contact_force), c);
  CHECK(std::abs(w.moment.z() - k * phi) < tolerance * k * phi);
}

TEST_CASE("a contact that holds the tip where the free finger rests carries no force")
{
  const ChainModel model =
    uniform_finger(4, 0.01, Eigen::Vector3d(0.05, 0.05, 0.02), Eigen::Vector3d(0, 0, 3e-7));
  ChainLoad load;
  load.pressure = 2e4; // J_p p = 6e-3 N m per joint: 0.3 rad each
  ChainEquilibrium free(model);
  const Equilibrium rest = free.solve(load);
  REQUIRE(rest.converged);
  const Eigen::Vector3d tip = free.pose().tip_position;

  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(load, tip, 0.9 * rest.angles);
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK((result.angles - rest.angles).lpNorm<Eigen::Infinity>() < tolerance);
  // The contact's scale: the pressure torque over the finger's length, 0.15 N.
  CHECK(result.contact_force.norm() < tolerance * 0.15);
}

TEST_CASE("the constrained solve refuses non-finite input")
{
  const ChainModel          model = uniform_finger(2, 0.01, Eigen::Vector3d(1, 1, 1));
  TipConstrainedEquilibrium solver(model);
  CHECK_THROWS_AS(solver.solve(ChainLoad{}, Eigen::Vector3d(NAN, 0, 0), Eigen::VectorXd::Zero(6)),
                  std::invalid_argument);
  CHECK_THROWS_AS(solver.solve(ChainLoad{}, Eigen::Vector3d(0.02, 0, 0), Eigen::VectorXd::Zero(3)),
                  std::invalid_argument);
}
