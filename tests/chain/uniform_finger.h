#pragma once
// A straight finger of n equal links of length a along +x with the same
// stiffness at every joint: the closed-form cases of the chain tests.
#include <softchain/chain/chain_model.h>

namespace softchain::chain::testing
{
  inline KinematicChain straight_chain(int n, double a)
  {
    std::vector<Eigen::Vector3d> joints;
    for (int i = 0; i < n; ++i)
      joints.emplace_back((i + 0.5) * a, 0.0, 0.0);
    return KinematicChain(joints, Eigen::Vector3d(n * a, 0.0, 0.0));
  }

  // Stiffness k = (k_psi, k_theta, k_phi) at every joint and J_p = jp at every joint.
  inline ChainModel uniform_finger(int n, double a, const Eigen::Vector3d &k,
                                   const Eigen::Vector3d &jp = Eigen::Vector3d::Zero())
  {
    return ChainModel("uniform", straight_chain(n, a),
                      JointStiffness(std::vector<Eigen::Vector3d>(n, k)),
                      PressureActuation(jp.replicate(n, 1)));
  }
} // namespace softchain::chain::testing
