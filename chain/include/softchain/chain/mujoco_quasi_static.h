#pragma once
// MujocoQuasiStatic: MuJoCo's quasi-static limit of a finger exported by
// MjcfExport, the state the chain's equilibrium describes. Gravity off (the
// chain has none); at each pressure, and with a dead force at the tip site,
// MuJoCo steps with the hinges' damping from its current state until it is
// at rest: every joint speed below 1e-11 rad/s and every hinge's unbalanced
// torque (MuJoCo's net force, qfrc_smooth) below its stiffness k times
// 1e-12 rad, i.e. an angle error below 1e-12 rad. The speed alone is not
// enough: the finger's bending modes are underdamped (damping time c / k =
// 0.01 s against periods of ~0.1 s), and a turning point of an oscillation
// has no speed but 1e-9 rad left to go. Successive calls at increasing
// pressures are a staircase ramp slow enough to be static. The pressure
// either sets the model from the
// MJCF's tables (MujocoPressureActuation, exact at every pressure) or only
// drives the motor of the exported constants K(p*), J_p(p*) (plain MuJoCo).
#include <softchain/chain/mujoco_pressure_actuation.h>

#include <mujoco/mujoco.h>

#include <Eigen/Core>

#include <optional>
#include <string>

namespace softchain::chain
{
  struct MujocoRestPose
  {
    Eigen::VectorXd angles; // qpos, the hinges in the chain's angle order
    Eigen::Vector3d tip;    // site "tip", world, m
    long            steps;  // MuJoCo steps to rest
  };

  class MujocoQuasiStatic
  {
  public:
    enum class Pressure
    {
      tables,            // MujocoPressureActuation at every pressure
      exported_constants // the MJCF's own fields (plain MuJoCo)
    };

    // Loads the MJCF at `path`; data::InputError with MuJoCo's message if
    // it cannot, or (Pressure::tables) if it has no pressure tables.
    MujocoQuasiStatic(const std::string &path, Pressure pressure);
    ~MujocoQuasiStatic();
    MujocoQuasiStatic(const MujocoQuasiStatic &)            = delete;
    MujocoQuasiStatic &operator=(const MujocoQuasiStatic &) = delete;

    // At rest under `pressure` (Pa) and the dead tip force (N, world);
    // std::runtime_error if MuJoCo is not at rest after 2e6 steps.
    MujocoRestPose rest_pose(double pressure, const Eigen::Vector3d &tip_force = Eigen::Vector3d::Zero());

  private:
    void apply_tip_force(const Eigen::Vector3d &force);
    bool at_rest() const;

    mjModel                               *model_;
    mjData                                *data_;
    std::optional<MujocoPressureActuation> actuation_;
    int                                    tip_site_, pressure_motor_;
  };
} // namespace softchain::chain
