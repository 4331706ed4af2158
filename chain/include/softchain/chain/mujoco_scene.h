#pragma once
// MujocoScene: the finger exported by MjcfExport in a MuJoCo world with one
// rigid obstacle of the .prm's subsection Contact (data::ObstacleRecord), or
// none. The obstacle is a MuJoCo primitive fixed in the world:
//
//   plane     geom plane through Position, its z axis along Normal
//   sphere    geom sphere of Radius about Position
//   cylinder  geom cylinder of Radius along Axis through Position; the
//             FEM's cylinder is infinite, MuJoCo's is 2 x 0.1 m long
//   box       geom box of Half sizes about Position, axis-aligned
//
// The finger touches it with its links' capsules (MjcfExport), radius
// `collision_radius` (the exported radius if 0): an explicit contact pair per
// link and the obstacle, frictionless (condim 1) when Friction = 0 as in the
// FEM's contact samples, else Coulomb's cone (condim 3) of that coefficient.
// Gravity is off, as in the chain and the FEM's contact samples; the time
// step is 5 ms (the exported 1 ms gives the same steady forces). The links
// keep the masses of the exported capsules: the steady contact force does
// not depend on them. The scene's MJCF is written to `scene_path`, loaded
// from there, and the finger set to pressures by MujocoPressureActuation.
#include <softchain/chain/mujoco_pressure_actuation.h>
#include <softchain/data/actuation_database.h>
#include <softchain/data/obstacle_record.h>

#include <mujoco/mujoco.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace softchain::chain
{
  // One contact of the finger with the obstacle.
  struct ObstacleContact
  {
    int             body;     // the finger's body (link) in contact
    Eigen::Vector3d position; // MuJoCo's contact point, world, m
    Eigen::Vector3d force;    // what the obstacle receives, world, N
  };

  class MujocoScene
  {
  public:
    // data::InputError naming the obstacle and its parameter if MuJoCo has
    // no primitive for it (Shape) or it moves (Motion: the scene holds it
    // still), or with MuJoCo's message if the finger's MJCF cannot be loaded.
    MujocoScene(const std::string &finger_mjcf, const std::optional<data::ObstacleRecord> &obstacle,
                double collision_radius, const std::string &scene_path);
    ~MujocoScene();
    MujocoScene(const MujocoScene &)            = delete;
    MujocoScene &operator=(const MujocoScene &) = delete;

    mjModel                       *model() { return model_; }
    mjData                        *data() { return data_; }
    const mjModel                 *model() const { return model_; }
    const mjData                  *data() const { return data_; }
    const MujocoPressureActuation &actuation() const { return *actuation_; }
    bool                           has_obstacle() const { return obstacle_geom_ >= 0; }

    // MuJoCo's current contacts with the obstacle (none without obstacle).
    std::vector<ObstacleContact> obstacle_contacts() const;
    // Their total force on the obstacle, world axes, N.
    Eigen::Vector3d obstacle_force() const;
    // Tip site position (m) and the last link's orientation (quaternion w x y z), world.
    Eigen::Vector3d tip_position() const;
    Eigen::Vector4d tip_orientation() const;

  private:
    mjModel                               *model_;
    mjData                                *data_;
    std::optional<MujocoPressureActuation> actuation_;
    int                                    obstacle_geom_, tip_site_;
  };

  // The capsule radius that puts the capsules' underside on the FEM mesh's
  // palm (its lowest y) at rest: the lowest joint's height above it
  // (`tables` at pressure 0); data::InputError if a joint lies below it.
  double palm_capsule_radius(const data::MeshRecord &mesh, const PressureTables &tables);
} // namespace softchain::chain
