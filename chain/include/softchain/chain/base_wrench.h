#pragma once
// base_wrench: the wrench that the loads on the chain transmit to its clamped
// base, as a force/torque sensor under the base measures it (the paper's
// validation, Sec. IV-B):
//   F = sum_k f_k,     M = sum_k (x_k - O) x f_k,
// f_k the point loads (a contact force included) at their current positions
// x_k, O the point the moment is taken about (e.g. the base face's centroid;
// the base is fixed, so world axes are the base frame). The pressure's joint
// torques J_p p are internal to the finger and transmit no wrench.
#include <softchain/chain/chain_load.h>
#include <softchain/chain/kinematic_chain.h>
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

namespace softchain::chain
{
  struct Wrench
  {
    Eigen::Vector3d force  = Eigen::Vector3d::Zero(); // N
    Eigen::Vector3d moment = Eigen::Vector3d::Zero(); // N m
  };

  Wrench base_wrench(const KinematicChain &chain, const ChainPose &pose, const ChainLoad &load,
                     const Eigen::Vector3d &moment_point);
} // namespace softchain::chain
