// TipConstrainedEquilibrium and base_wrench against closed forms: a single
// joint and a two-link planar chain with the tip held by a point contact, a
// three-link planar chain and a twisted joint with the tip frame held, the
// free equilibrium recovered when the contact holds the tip where the finger
// would be anyway; and the dead couple's tangent against finite differences.
#include <softchain/chain/base_wrench.h>
#include <softchain/chain/tip_constrained_equilibrium.h>

#include "uniform_finger.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

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

TEST_CASE("three-link planar chain with its tip frame held: the angles, the contact force and "
          "couple of the statics")
{
  // Joints at x = a/2, 3a/2, 5a/2, tip at 3a: links a, a, a/2; bending
  // stiffness k about z, stiff out of the plane. Holding the tip's position
  // and its angle in the plane fixes all three angles.
  const double     a = 0.01, k = 0.02;
  const ChainModel model = uniform_finger(3, a, Eigen::Vector3d(50, 50, k));
  const std::vector<double> phi{0.3, 0.5, -0.2}, L{a, a, 0.5 * a};
  std::vector<Eigen::Vector3d> c{Eigen::Vector3d(0.5 * a, 0, 0)};
  double                       turned = 0;
  for (int i = 0; i < 3; ++i)
    {
      turned += phi[i];
      c.push_back(c.back() + L[i] * Eigen::Vector3d(std::cos(turned), std::sin(turned), 0));
    }
  const Eigen::Vector3d tip = c[3];
  TipTarget             target{tip, Eigen::Matrix3d(Eigen::AngleAxisd(turned, Eigen::Vector3d::UnitZ()))};

  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(ChainLoad{}, target, planar_angles({0.2, 0.4, 0.0}));
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK((result.angles - planar_angles(phi)).lpNorm<Eigen::Infinity>() < tolerance);

  // Statics: k phi_i = ((x_tip - c_i) x f)_z + m_z, i = 1..3, for f_x, f_y, m_z.
  Eigen::Matrix3d A;
  for (int i = 0; i < 3; ++i)
    A.row(i) << -(tip - c[i]).y(), (tip - c[i]).x(), 1.0;
  const Eigen::Vector3d fm = A.lu().solve(k * Eigen::Vector3d(phi[0], phi[1], phi[2]));
  const double          scale = fm.head<2>().norm(), moment_scale = k * std::abs(phi[0]);
  CHECK((result.contact_force.head<2>() - fm.head<2>()).norm() < tolerance * scale);
  CHECK(std::abs(result.contact_force.z()) < tolerance * scale);
  CHECK(std::abs(result.contact_moment.z() - fm.z()) < tolerance * moment_scale);
  CHECK(result.contact_moment.head<2>().norm() < tolerance * moment_scale);

  // The base (about the first joint) holds the first spring's moment.
  Wrench w = base_wrench(model.chain(), solver.pose(),
                         solver.with_contact(ChainLoad{}, result.contact_force), c[0]);
  w.moment += result.contact_moment;
  CHECK(std::abs(w.moment.z() - k * phi[0]) < tolerance * moment_scale);
}

TEST_CASE("a joint twisted by its held tip frame: the twist angle and the couple k_psi psi")
{
  // The tip lies on the twist axis, so a turn of the frame about x leaves it
  // in place: psi = beta and the contact is the couple k_psi beta about x.
  const double     a = 0.02, k_psi = 0.004, beta = 0.35;
  const ChainModel model = uniform_finger(1, a, Eigen::Vector3d(k_psi, 0.05, 0.05));
  TipTarget        target{Eigen::Vector3d(a, 0, 0),
                   Eigen::Matrix3d(Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitX()))};
  TipConstrainedEquilibrium solver(model);
  const auto result = solver.solve(ChainLoad{}, target, Eigen::VectorXd::Zero(3));
  INFO(result.failure);
  REQUIRE(result.converged);
  CHECK(std::abs(result.angles(0) - beta) < tolerance);
  CHECK(result.angles.tail<2>().norm() < tolerance);
  CHECK(std::abs(result.contact_moment.x() - k_psi * beta) < tolerance * k_psi * beta);
  CHECK(result.contact_moment.tail<2>().norm() < tolerance * k_psi * beta);
  CHECK(result.contact_force.norm() < tolerance * k_psi * beta / a);
}

TEST_CASE("the dead couple's tangent is the derivative of its generalised force")
{
  // Central differences of W(q)^T m against G: truncation O(h^2) ~ 1e-12 and
  // round-off ~ 1e-16 / h = 1e-10 relative to |m|; 1e-8 leaves a margin.
  const ChainModel      model = uniform_finger(3, 0.01, Eigen::Vector3d(1, 1, 1));
  const Eigen::Vector3d m(0.3, -0.2, 0.5);
  Eigen::VectorXd       q(9);
  q << 0.1, -0.3, 0.4, 0.2, 0.25, -0.5, -0.15, 0.35, 0.6;
  ChainPose pose = model.chain().rest_pose();
  model.chain().update_pose(q, pose);
  const Eigen::MatrixXd G = dead_couple_stiffness(pose, m);
  const double          h = 1e-6;
  for (int l = 0; l < 9; ++l)
    {
      Eigen::VectorXd plus = q, minus = q;
      plus(l) += h;
      minus(l) -= h;
      model.chain().update_pose(plus, pose);
      const Eigen::VectorXd up = angular_jacobian(pose).transpose() * m;
      model.chain().update_pose(minus, pose);
      const Eigen::VectorXd down = angular_jacobian(pose).transpose() * m;
      INFO("column " << l);
      CHECK(((up - down) / (2 * h) - G.col(l)).lpNorm<Eigen::Infinity>() < 1e-8 * m.norm());
    }
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
