#pragma once
// ChainLoad: what acts on the finger in one equilibrium problem, the chain
// tier's version of the database's actuation S = (p, force points, forces)
// and, for a contact sample, its obstacles.
#include <softchain/data/obstacle_record.h>

#include <Eigen/Core>
#include <vector>

namespace softchain::chain
{
  // A dead point force: applied at a material point of the finger (given by
  // its reference position) with a fixed direction in world axes.
  struct PointLoad
  {
    Eigen::Vector3d reference_point = Eigen::Vector3d::Zero(); // m
    Eigen::Vector3d force           = Eigen::Vector3d::Zero(); // N, world
  };

  struct ChainLoad
  {
    double                 pressure = 0.0; // Pa
    std::vector<PointLoad> point_loads;
    // Rigid obstacles the finger may touch (ChainContact), at the end of
    // their motion; none: a free finger.
    std::vector<data::ObstacleRecord> obstacles = {};
  };
} // namespace softchain::chain
