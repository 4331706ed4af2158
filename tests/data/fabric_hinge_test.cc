// FabricHinge against its definition: the torque is the energy's gradient
// and the tangent the torque's (central differences), the pressure state is
// in equilibrium, the law is mirror-symmetric and convex, and a lateral
// increment at rest drops the finger in its plane on either side, by the
// closed form of the one taut edge.
#include <softchain/data/fabric_hinge.h>

#include <Eigen/Dense>

#include <catch2/catch.hpp>

using softchain::data::FabricHinge;

namespace
{
  FabricHinge hinge(double theta_0)
  {
    FabricHinge h;
    h.k       = Eigen::Vector3d(0.06, 0.05, 0.15);
    h.kappa   = 0.5;
    h.r       = 0.3;
    h.theta_0 = theta_0;
    return h;
  }

  // Increments where both, one or no edge is taut (theta_0 = 0.01: taut
  // while |d theta| < 0.01 + 0.3 d phi), none within 1e-4 of a kink.
  const std::vector<Eigen::Vector3d> increments = {
    {0.001, 0.004, -0.002}, {-0.02, 0.03, 0.01}, {0.01, -0.05, -0.02}, {0.0, 0.002, -0.08}};

  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, -1, 1).asDiagonal();
} // namespace

TEST_CASE("the fabric hinge's torque and tangent are the derivatives of its energy")
{
  // W is piecewise quadratic and T piecewise linear: away from the kinks
  // central differences are exact up to round-off, eps |W| / h ~ 1e-16 /
  // 1e-6 relative to the torque, so 1e-8 of the largest entry.
  const double h = 1e-6;
  for (const double theta_0 : {0.0, 0.01})
    for (const Eigen::Vector3d &d : increments)
      {
        const FabricHinge::Value v = hinge(theta_0).evaluate(d);
        Eigen::Vector3d          gradient;
        Eigen::Matrix3d          jacobian;
        for (int a = 0; a < 3; ++a)
          {
            const Eigen::Vector3d e     = h * Eigen::Vector3d::Unit(a);
            const auto            plus  = hinge(theta_0).evaluate(d + e);
            const auto            minus = hinge(theta_0).evaluate(d - e);
            gradient[a]                 = (plus.energy - minus.energy) / (2 * h);
            jacobian.col(a)             = (plus.torque - minus.torque) / (2 * h);
          }
        CHECK((gradient - v.torque).cwiseAbs().maxCoeff() < 1e-8 * v.torque.cwiseAbs().maxCoeff());
        CHECK((jacobian - v.tangent).cwiseAbs().maxCoeff() < 1e-8 * v.tangent.cwiseAbs().maxCoeff());
        CHECK(v.tangent.isApprox(v.tangent.transpose(), 1e-15));
        CHECK(v.tangent.llt().info() == Eigen::Success); // convex: k > 0 alone is positive definite
      }
}

TEST_CASE("the pressure state is in equilibrium and the law is mirror-symmetric")
{
  for (const double theta_0 : {0.0, 0.01})
    {
      const FabricHinge::Value rest = hinge(theta_0).evaluate(Eigen::Vector3d::Zero());
      CHECK(rest.energy == 0.0);
      CHECK(rest.torque.isZero(0.0));
      // Mirroring about the mid-plane (psi, theta -> -psi, -theta) swaps
      // the edges: T(M d) = M T(d), W(M d) = W(d), exactly.
      for (const Eigen::Vector3d &d : increments)
        {
          const auto v = hinge(theta_0).evaluate(d), m = hinge(theta_0).evaluate(mirror * d);
          CHECK((m.torque - mirror * v.torque).cwiseAbs().maxCoeff() < 1e-15 * v.torque.norm());
          CHECK(m.energy == Approx(v.energy).epsilon(1e-14));
        }
    }
}

TEST_CASE("a lateral turn at rest stretches one edge, which bends the joint in its plane either way")
{
  // theta_0 = 0: at d = (0, t, phi) only the edge with e = |t| + r phi > 0
  // is taut, T_phi = k_phi phi + kappa r (|t| + r phi) = 0 at
  //   phi* = -kappa r |t| / (k_phi + kappa r^2),
  // the same for t and -t, and T_theta = k_theta t + kappa sign(t) (|t| + r phi*).
  const FabricHinge h     = hinge(0.0);
  const double      t     = 0.02;
  const double      phi   = -h.kappa * h.r * t / (h.k[2] + h.kappa * h.r * h.r);
  for (const double sign : {1.0, -1.0})
    {
      const FabricHinge::Value v = h.evaluate(Eigen::Vector3d(0.0, sign * t, phi));
      CHECK(std::abs(v.torque[2]) < 1e-16);
      CHECK(v.torque[1] == Approx(sign * (h.k[1] * t + h.kappa * (t + h.r * phi))).epsilon(1e-14));
      CHECK(v.torque[0] == 0.0);
    }
  // In-plane bending that shortens the layer (r phi < 0) leaves both edges
  // slack: the springs alone.
  const FabricHinge::Value slack = h.evaluate(Eigen::Vector3d(0.0, 0.0, -0.05));
  CHECK(slack.torque[2] == Approx(h.k[2] * -0.05).epsilon(1e-15));
  CHECK(slack.tangent.isApprox(Eigen::Matrix3d(h.k.asDiagonal()), 1e-15));
}

namespace
{
  // The inflated finger's layer: pre-stretched, and free to stretch on its
  // own against the silicone (layer_give g = kappa / k_axial).
  FabricHinge prestressed(double give)
  {
    FabricHinge h = hinge(0.004);
    h.kappa       = 4.0;
    h.r           = 1.0;
    h.layer_give  = give;
    return h;
  }
} // namespace

TEST_CASE("with the layer's give the torque and tangent are still the energy's derivatives")
{
  // W(d) = min_e V(e, d) is piecewise quadratic: central differences are
  // exact up to round-off away from its kinks (1e-8 as above). The
  // increments have both, one or no edge taut (theta_0 = 0.004, the layer's
  // stretch e* moving with r d_phi).
  const double h = 1e-6;
  for (const double give : {0.5, 8.0})
    for (const Eigen::Vector3d &d : {Eigen::Vector3d(0.001, 0.002, 0.001), Eigen::Vector3d(-0.02, 0.03, 0.01),
                                     Eigen::Vector3d(0.01, -0.05, -0.02), Eigen::Vector3d(0.0, 0.001, -0.2)})
      {
        const FabricHinge        law = prestressed(give);
        const FabricHinge::Value v   = law.evaluate(d);
        Eigen::Vector3d          gradient;
        Eigen::Matrix3d          jacobian;
        for (int a = 0; a < 3; ++a)
          {
            const Eigen::Vector3d e     = h * Eigen::Vector3d::Unit(a);
            const auto            plus  = law.evaluate(d + e);
            const auto            minus = law.evaluate(d - e);
            gradient[a]                 = (plus.energy - minus.energy) / (2 * h);
            jacobian.col(a)             = (plus.torque - minus.torque) / (2 * h);
          }
        CHECK((gradient - v.torque).cwiseAbs().maxCoeff() < 1e-8 * v.torque.cwiseAbs().maxCoeff());
        CHECK((jacobian - v.tangent).cwiseAbs().maxCoeff() < 1e-8 * v.tangent.cwiseAbs().maxCoeff());
        CHECK(v.tangent.llt().info() == Eigen::Success);
        // The pressure state stays in equilibrium, and the law mirror-symmetric.
        CHECK(law.evaluate(Eigen::Vector3d::Zero()).torque.isZero(0.0));
        CHECK((law.evaluate(mirror * d).torque - mirror * v.torque).norm() < 1e-14 * v.torque.norm());
      }
}

TEST_CASE("a pre-stressed layer that gives holds a lateral turn stiffly up to its knee, then softly")
{
  // Both edges taut (|d_theta| < theta_0, d_phi = 0): e* = 0 and the
  // lateral slope is k_theta + 2 kappa; in the plane the layer's stretch
  // follows r d_phi, leaving k_phi + 2 kappa r^2 / (1 + 2 g). Past the knee
  // one edge is taut: e* = (theta_0 - |d_theta|) g / (1 + g) and the slope
  // k_theta + kappa / (1 + g) (the Schur complement of the header).
  const double      give = 8.0;
  const FabricHinge law  = prestressed(give);
  const double      t    = 0.5 * law.theta_0;
  const auto        stiff = law.evaluate(Eigen::Vector3d(0.0, t, 0.0));
  CHECK(law.layer_stretch(Eigen::Vector3d(0.0, t, 0.0)) == 0.0);
  CHECK(stiff.torque[1] == Approx((law.k[1] + 2 * law.kappa) * t).epsilon(1e-14));
  CHECK(stiff.tangent(2, 2) ==
        Approx(law.k[2] + 2 * law.kappa * law.r * law.r / (1 + 2 * give)).epsilon(1e-14));
  const double past = 5.0 * law.theta_0;
  const auto   soft = law.evaluate(Eigen::Vector3d(0.0, past, 0.0));
  CHECK(law.layer_stretch(Eigen::Vector3d(0.0, past, 0.0)) ==
        Approx((law.theta_0 - past) * give / (1 + give)).epsilon(1e-14));
  CHECK(soft.tangent(1, 1) == Approx(law.k[1] + law.kappa / (1 + give)).epsilon(1e-14));
  // The one taut edge also pulls the joint in its plane (w = (0, -u, r)).
  CHECK(std::abs(soft.torque[2]) > 0.1 * std::abs(soft.torque[1]));
  // Without give the layer's stretch is fixed: the classic hinge.
  FabricHinge fixed = law;
  fixed.layer_give  = 0.0;
  CHECK(fixed.layer_stretch(Eigen::Vector3d(0.0, past, 0.0)) == 0.0);
}
