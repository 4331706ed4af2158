#pragma once
// Obstacles and collision surfaces of the chain's contact tests: a table, a
// cylinder, and a straight finger with a palm of points under its links.
#include <softchain/chain/chain_model.h>
#include <softchain/chain/collision_surface.h>

#include "uniform_finger.h"

#include <Eigen/Core>

#include <vector>

namespace softchain::chain::testing
{
  inline softchain::data::ObstacleRecord plane(const double y)
  {
    softchain::data::ObstacleRecord o;
    o.name      = "table";
    o.shape     = "plane";
    o.position  = {0.0, y, 0.0};
    o.direction = {0.0, 1.0, 0.0};
    return o;
  }

  inline softchain::data::ObstacleRecord cylinder(const Eigen::Vector3d &centre, const double radius)
  {
    softchain::data::ObstacleRecord o;
    o.name      = "cylinder";
    o.shape     = "cylinder";
    o.position  = {centre.x(), centre.y(), centre.z()};
    o.direction = {0.0, 0.0, 1.0};
    o.radius    = radius;
    return o;
  }

  // Points under each link of a straight chain of n links of length a (joint
  // i at (i + 1/2) a): `per_link` along it, `depth` below the joint line,
  // at z = +-w; with `rigid_side`, those at z = -w do not give (a skin
  // moves only those at +w).
  inline CollisionSurface palm_points(const int n, const double a, const int per_link, const double depth,
                                      const double w, const bool rigid_side = false)
  {
    std::vector<int>             links;
    std::vector<Eigen::Vector3d> offsets;
    std::vector<char>            gives;
    for (int b = 0; b < n; ++b)
      for (int s = 0; s < per_link; ++s)
        for (const double z : {-w, w})
          {
            links.push_back(b);
            offsets.emplace_back(a * (s + 0.5) / per_link, -depth, z);
            gives.push_back(!rigid_side || z > 0);
          }
    return CollisionSurface(links, {{0.0, offsets}}, n, gives);
  }

  // Six links of 15 mm, k_phi 0.05 N m/rad, J_p p bending them down by
  // 0.06 rad each at 30 kPa, with a palm 3 mm below the joints.
  inline ChainModel finger_with_palm()
  {
    ChainModel model = uniform_finger(6, 0.015, {0.3, 0.2, 0.05}, {0.0, 0.0, -1e-7});
    model.set_collision_surface(palm_points(6, 0.015, 4, 0.003, 0.005));
    return model;
  }
} // namespace softchain::chain::testing
