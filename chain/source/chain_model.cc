#include <softchain/chain/chain_model.h>

#include <stdexcept>

namespace softchain::chain
{
  ChainModel::ChainModel(std::string name, KinematicChain chain, JointStiffness stiffness,
                         PressureActuation actuation)
    : name_(std::move(name))
    , chain_(std::move(chain))
    , stiffness_(std::move(stiffness))
    , actuation_(std::move(actuation))
  {
    if (stiffness_.n_joints() != chain_.n_joints() ||
        actuation_.rest_torque_per_pascal().size() != chain_.n_angles())
      throw std::invalid_argument("ChainModel: joint counts of geometry, stiffness and J_p differ");
  }

  void ChainModel::set_twist_joints(std::vector<bool> twist_joints)
  {
    if (static_cast<int>(twist_joints.size()) != chain_.n_joints())
      throw std::invalid_argument("ChainModel: one twist-joint flag per joint needed");
    twist_joints_ = std::move(twist_joints);
  }
} // namespace softchain::chain
