#pragma once
// ContactScene: the .prm subsection "Contact", checked: the rigid obstacles
// the finger may touch (each a nested subsection, named by the user), the
// boundary groups that may touch them and the constants of the contact law.
//
//   subsection Contact
//     set Surfaces = all           # or boundary groups: tip, outer, cavity
//     subsection table
//       set Shape    = plane       # plane | sphere | cylinder | box | stl
//       set Position = 0, -0.02, 0 # a point of the plane, a centre, a point of the axis
//       set Normal   = 0, 1, 0     # plane
//       set Motion   = 0, 0.005, 0 # translation along the load path, m
//       set Motion rotation = 0, 0, 0.1 # turn along the load path about Motion pivot, rad
//     end
//     subsection stone
//       set Shape = stl
//       set File  = stone.stl       # relative to the .prm's directory, m
//     end
//     set Obstacles in solve = all # or none, or obstacle names
//   end
// `softchain solve` puts the obstacles of `Obstacles in solve` in its scene;
// the sample sweep puts in each contact sample's scene the obstacle that
// the sample names (subsection Samples, Contact samples).
#include <softchain/geometry/rigid_obstacle.h>

#include <softchain/data/obstacle_record.h>
#include <softchain/data/prm_file.h>

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace softchain::geometry
{
  // An obstacle as the .prm or a database sample describes it (name, shape,
  // pose, friction, motion) and its signed distance.
  struct Obstacle
  {
    data::ObstacleRecord                 description;
    std::shared_ptr<const RigidObstacle> body;

    // Builds the body; an InputError if the description is no obstacle
    // (a zero normal or axis, a radius or half size <= 0, mu < 0, an open
    // or inconsistently oriented triangle surface).
    explicit Obstacle(const data::ObstacleRecord &description);

    const std::string &name() const { return description.name; }
    double             friction() const { return description.friction; }
    // The pose at path parameter t in [0, 1] from the rest pose (0): turned
    // by t Motion rotation about Motion pivot, then moved by t Motion.
    RigidTransform     pose(double t) const;
  };

  struct ContactScene
  {
    std::vector<Obstacle> obstacles; // none: no contact
    // The names of the obstacles `softchain solve` uses (Obstacles in solve).
    std::vector<std::string> in_solve;
    // Boundary groups that may touch: "all" (every boundary face but the
    // clamped base) or names among tip, outer, cavity.
    std::vector<std::string> surfaces{"all"};
    // The penalty per quadrature point, epsilon = factor E / h (E the
    // element's Young's modulus, h its face size): the penetration is then
    // t_N / (factor E) of h, and Uzawa's updates take it below the
    // tolerance. Measured on the demo bender pressed onto a plane at 40 kPa:
    // with friction (mu >= 0.2), factor 100 stopped on inverted elements at
    // 3-4 kPa, factor 10 converged for mu from 0 to 1 in 20-23 load steps,
    // with the same frictionless force to three digits (docs/contact.md).
    double penalty_factor = 10;
    // A converged state whose deepest penetration exceeds this fraction of
    // the local face size takes augmented-Lagrangian (Uzawa) updates.
    double penetration_tolerance = 0.01;
    unsigned int max_augmentations = 10;
    std::string  file; // the .prm it was read from, for messages

    bool empty() const { return obstacles.empty(); }

    // The obstacles' descriptions, in order.
    std::vector<data::ObstacleRecord> descriptions() const;
    // The contact constants (Surfaces, Penalty factor, Penetration
    // tolerance, Maximum augmentations) as canonical text: a contact
    // sample's cache key holds it, as they change its solution.
    std::string law_text() const;
    // The same constants with the obstacles `chosen` instead (a contact
    // sample's scene).
    ContactScene with(const std::vector<data::ObstacleRecord> &chosen) const;
    // The obstacle named `name`, or nullptr.
    const Obstacle *find(const std::string &name) const;

    // Reads the subsection "Contact" (absent: no obstacles). Throws
    // InputError naming file, line and parameter.
    static ContactScene read(const data::PrmFile &file);
    // The scene of `softchain solve`: the obstacles of `in_solve`.
    ContactScene solve_scene() const;
  };
} // namespace softchain::geometry
