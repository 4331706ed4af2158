#pragma once
// FabricHinge: the law of one joint under forces, where a tension-only
// fabric layer (the strain-limiting layer of a pneumatic finger) runs across
// it. The reduction fits it (reduction::FabricHingeFit), the chain evaluates
// it (chain::JointForceLaw); both use this class.
//
// In the joint's angle increments d = (d_psi, d_theta, d_phi) over the
// pressure-only state, the solid is three linear springs k = (k_psi,
// k_theta, k_phi) and the layer two edge fibres u = -1, +1 at its sides,
// stretched (in angle units) by
//   e_u(d) = theta_0 - u d_theta + r d_phi,   grad e_u = w_u = (0, -u, r),
// theta_0 >= 0 their pre-stretch by the pressure, r the in-plane lever of
// the layer relative to its lateral one. Each carries a tension kappa <e_u>+
// (<x>+ = max(x, 0): a fabric goes slack rather than compress). Energy,
// torque and tangent of the increment:
//   W(d) = 1/2 sum_a k_a d_a^2 + kappa/2 sum_u (<e_u>+^2 - theta_0^2 - 2 theta_0 w_u . d)
//   T(d) = diag(k) d + kappa sum_u (<e_u>+ - theta_0) w_u
//   H(d) = diag(k) + kappa sum_{u: e_u > 0} w_u w_u^T
// so T(0) = 0 (the pressure state is in equilibrium), W is convex and C1,
// and W is mirror-symmetric about the finger's mid-plane (psi, theta -> -psi,
// -theta swaps the edges). What it reproduces (docs/chain_fidelity.md): a
// lateral force at rest stretches one edge only, whose tension also bends
// the finger in its plane, so the tip drops whichever side it is pushed; a
// pre-stretched layer (theta_0 > 0) holds small lateral loads stiffly with
// both edges and softens when one goes slack.

#include <Eigen/Core>

namespace softchain::data
{
  struct FabricHinge
  {
    Eigen::Vector3d k       = Eigen::Vector3d::Zero(); // N m / rad: k_psi, k_theta, k_phi
    double          kappa   = 0.0;                      // N m / rad, the fibres' stiffness
    double          r       = 0.0;                      // in-plane over lateral lever
    double          theta_0 = 0.0;                      // rad, pre-stretch

    struct Value
    {
      double          energy = 0.0;
      Eigen::Vector3d torque = Eigen::Vector3d::Zero();
      Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();
    };
    Value evaluate(const Eigen::Vector3d &d) const;

    // T(d) = diag(k) d + kappa g(d): the fibres' part per unit kappa, for a
    // fit linear in (k, kappa) at fixed r and theta_0.
    Eigen::Vector3d fibre_torque_per_kappa(const Eigen::Vector3d &d) const;
  };
} // namespace softchain::data
