// The damped dynamic step: it comes to rest at the static equilibrium, and a
// single joint oscillates and decays as its linear closed form predicts.
#include <softchain/chain/chain_dynamics.h>

#include "uniform_finger.h"

#include <catch2/catch.hpp>

using namespace softchain::chain;
using softchain::chain::testing::uniform_finger;

TEST_CASE("damped dynamics comes to rest at the static equilibrium")
{
  const ChainModel model = uniform_finger(9, 0.01, Eigen::Vector3d(0.2, 0.05, 0.05),
                                          Eigen::Vector3d(0.0, 0.0, 2e-7));
  const ChainLoad  load{5e4, {{{0.09, 0.0, 0.0}, {0.0, 0.3, 0.05}}}};
  ChainEquilibrium statics(model);
  const Equilibrium e = statics.solve(load);
  REQUIRE(e.converged);

  // 1 g per link; damping 0.01 s times the stiffness.
  const Eigen::VectorXd damping = 0.01 * model.stiffness().diagonal(load.pressure);
  ChainDynamics          dynamics(model, std::vector<double>(9, 1e-3), damping);
  dynamics.set_load(load);
  int steps = 0;
  for (; steps < 5000; ++steps)
    {
      dynamics.step(1e-3);
      if (dynamics.velocities().lpNorm<Eigen::Infinity>() < 1e-12)
        break;
    }
  INFO("steps: " << steps);
  CHECK(steps < 5000);
  // At rest r(q) = 0 exactly (the step's fixed point); the remaining
  // velocity 1e-12 rad/s stands for an unbalanced torque c v, i.e. an angle
  // error of c v / k = 1e-14 rad, below the statics' own tolerance 1e-10.
  CHECK((dynamics.angles() - e.angles).lpNorm<Eigen::Infinity>() < 1e-9);
}

TEST_CASE("one joint swings as a damped oscillator")
{
  // One joint at a/2, its link to the tip at a, the mass m at the link's
  // midpoint 3a/4, a/4 from the joint: rotating about z, inertia I = m (a/4)^2, so I phi'' + c phi' + k phi = tau. Implicit Euler with a
  // small step (h omega = 0.01) follows the exact response to first order in
  // h: phi(t) = tau/k (1 - e^{-zeta w t} (cos w_d t + zeta w / w_d sin w_d t)).
  const double     a = 0.02, m = 0.01, k = 0.05, c = 1e-5, tau = 0.01;
  const ChainModel model = uniform_finger(1, a, Eigen::Vector3d(k, k, k), Eigen::Vector3d(0, 0, tau));
  ChainDynamics dynamics(model, {m}, Eigen::Vector3d(c, c, c));
  dynamics.set_load({1.0, {}});
  const double inertia = m * a * a / 16, omega = std::sqrt(k / inertia);
  const double zeta = c / (2 * std::sqrt(k * inertia)), damped = omega * std::sqrt(1 - zeta * zeta);
  const double h = 0.01 / omega, t = 3.0 / omega; // half a period
  for (int s = 0; s < std::lround(t / h); ++s)
    dynamics.step(h);
  const double exact = tau / k *
                       (1 - std::exp(-zeta * omega * t) *
                              (std::cos(damped * t) + zeta * omega / damped * std::sin(damped * t)));
  // Backward Euler damps numerically at rate h omega^2 / 2 per unit time:
  // relative error ~ h omega * omega t / 2 = 0.01 * 3 / 2 = 1.5 %; 3 % bound.
  CHECK(dynamics.angles()[2] == Approx(exact).epsilon(0.03));
  CHECK(std::abs(dynamics.angles()[0]) + std::abs(dynamics.angles()[1]) < 1e-12);
}
