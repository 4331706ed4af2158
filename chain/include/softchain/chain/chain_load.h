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

  // Where a surface point sticks to an obstacle with friction: the state
  // one load step of a frictional load path (FrictionalLoadPath) hands to
  // the next (ChainContact's friction has the equations).
  struct StickAnchor
  {
    int             link = 0, point = 0, obstacle = 0; // surface point `point` of `link`
    Eigen::Vector3d position = Eigen::Vector3d::Zero(); // a, m, world: where the point sticks
    Eigen::Vector3d normal   = Eigen::Vector3d::Zero(); // n of the obstacle there
    double          normal_force = 0.0;                  // N >= 0, N
  };

  struct ChainLoad
  {
    double                 pressure = 0.0; // Pa
    std::vector<PointLoad> point_loads;
    // Rigid obstacles the finger may touch (ChainContact), at path
    // parameter `path` of their motion (1: its end); none: a free finger.
    std::vector<data::ObstacleRecord> obstacles = {};
    double                            path      = 1.0;
    // The stick anchors of obstacles with friction, sorted by link (none:
    // every point starts to slide freely, the frictionless answer).
    std::vector<StickAnchor> anchors = {};
  };
} // namespace softchain::chain
