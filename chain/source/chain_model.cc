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
} // namespace softchain::chain
