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
//
// The layer's line may also stretch on its own (layer_give g > 0): the
// silicone holds the layer's mean stretch e with a stiffness kappa / g, and
// the pressure's axial pull balances the edges' pre-tension 2 kappa theta_0
// (as a pre-stressed section whose gas pulls its ends apart):
//   W(d) = min_e V(e, d),
//   V = 1/2 sum_a k_a d_a^2 + kappa [e^2 / (2 g) + 1/2 sum_u (<e_u>+^2 - theta_0^2)
//                                    - 2 theta_0 e - theta_0 sum_u w_u . d],
//   e_u = theta_0 + e + w_u . d,
// convex in (e, d) and so W in d. Its e*(d) solves the increasing, piecewise
// linear e / g + sum_u <e_u>+ = 2 theta_0; by the envelope theorem the torque
// keeps the form above with e* in e_u, and the tangent loses the layer's
// stretch (a Schur complement over the taut edges U):
//   H = diag(k) + kappa [sum_U w w^T - (sum_U w)(sum_U w)^T / (1/g + |U|)].
// What this adds: both edges taut, the layer resists a lateral turn by
// 2 kappa but an in-plane one hardly at all (e follows r d_phi); past the
// knee (the slack edge's pre-stretch used up, |d_theta| ~ theta_0) the one
// taut edge pulls with the pre-tension plus kappa g' (g' = 1 / (1 + g))
// times its stretch: the joint saturates at the pressure's pull and turns
// on like a joint at rest, bending in its plane as it does. g = 0 is the
// layer of fixed mean stretch above.

#include <Eigen/Core>

namespace softchain::data
{
  struct FabricHinge
  {
    Eigen::Vector3d k       = Eigen::Vector3d::Zero(); // N m / rad: k_psi, k_theta, k_phi
    double          kappa   = 0.0;                      // N m / rad, the fibres' stiffness
    double          r       = 0.0;                      // in-plane over lateral lever
    double          theta_0 = 0.0;                      // rad, pre-stretch
    double          layer_give = 0.0;                   // g = kappa / k_axial; 0: e = 0

    // e*(d): the layer's mean stretch at the increment d (0 without give).
    double layer_stretch(const Eigen::Vector3d &d) const;

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

  private:
    // The same at the layer's stretch e (layer_stretch(d)), computed once by evaluate().
    Eigen::Vector3d fibre_torque_per_kappa(const Eigen::Vector3d &d, double e) const;
  };
} // namespace softchain::data
