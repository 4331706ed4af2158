#pragma once
// ChainModel: one finger of the chain tier, i.e. the geometry (KinematicChain),
// the joint stiffness K and the pressure actuation J_p; everything the
// equilibrium K q = J_p p + J(q)^T f needs besides the load.
#include <softchain/chain/joint_stiffness.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/chain/pressure_actuation.h>

#include <string>

namespace softchain::chain
{
  class ChainModel
  {
  public:
    // Joint counts must agree; throws std::invalid_argument otherwise.
    ChainModel(std::string name, KinematicChain chain, JointStiffness stiffness,
               PressureActuation actuation);

    const std::string       &name() const { return name_; }
    const KinematicChain    &chain() const { return chain_; }
    const JointStiffness    &stiffness() const { return stiffness_; }
    const PressureActuation &actuation() const { return actuation_; }

  private:
    std::string       name_;
    KinematicChain    chain_;
    JointStiffness    stiffness_;
    PressureActuation actuation_;
  };
} // namespace softchain::chain
