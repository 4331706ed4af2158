#pragma once
// LinkCompliance: the links' own elasticity, in series with the joints.
// Rigid links cannot stretch or shear, the silicone between two joints can:
// when P10's curled tip is moved 5 mm along its base-tip chord (the
// direction in which the joints alone are stiffest), about 2 mm of it is
// its links' (docs/results.md, "The paper's validation experiment on P10").
// The model is the simplest that expresses this: every link is an isotropic
// linear spring in series with its joints, its compliance uniform per unit
// length along the chain, so that a point force f at the fraction s of the
// chain's length from joint 1 to the tip moves the tip by
//   delta = c(p) s f,
// c(p) [m/N] the compliance of all links together, fitted by the reduction
// to the chord samples (reduction/README.md) and interpolated in pressure
// like k_phi(p) (PiecewiseLinear). The deflection is first order: it moves
// the tip, not the joints' levers (the joint torques stay J(q)^T f), and it
// turns no frame; an isotropic deflection c f is parallel to f, so it leaves
// the moment of f about the base unchanged.
#include <softchain/chain/chain_load.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>

namespace softchain::chain
{
  class LinkCompliance
  {
  public:
    // c(p) in m/N against pressure; std::invalid_argument if a value is
    // negative or not finite.
    explicit LinkCompliance(PiecewiseLinear compliance);

    // c(p), m/N.
    double at(double pressure) const { return compliance_(pressure); }
    // The tip's deflection under `load`'s point forces, c(p) sum_k s_k f_k,
    // s_k = clamp((x_k - x_1) / (x_T - x_1), 0, 1) from the reference
    // positions of the load point x_k, joint 1 x_1 and the tip x_T along x.
    Eigen::Vector3d tip_deflection(const ChainLoad &load, const KinematicChain &reference) const;
    const PiecewiseLinear &table() const { return compliance_; }

  private:
    PiecewiseLinear compliance_;
  };
} // namespace softchain::chain
