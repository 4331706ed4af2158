#pragma once
// PressureRampSimulation: MuJoCo's finger in a MujocoScene under a slow
// pressure ramp. From rest at 0 the pressure rises linearly in time at
// `rate` to each target pressure in turn and holds it for `hold`; the
// finger is set to the pressure of every step (MujocoPressureActuation:
// stiffness K(p), pressure torque J_p(p) p and links U(p) of the chain).
// The hinges' damping c = k * damping time (MjcfExport: 0.01 s against the
// bending periods of ~0.1 s) settles each hold within a few periods; the
// steady contact force of a target is the mean of the obstacle's force over
// the last `average` seconds of its hold, its steady tip the mean of the
// tip site's position over the same steps.
//
// Time series, one row per `record_interval` (0: none), columns
//   joint angles:  time [s], pressure [Pa], one column per hinge
//                  (joint<i>_psi, joint<i>_theta, joint<i>_phi) [rad]
//   tip pose:      time, pressure, tip_x, tip_y, tip_z [m, site "tip"],
//                  tip_qw, tip_qx, tip_qy, tip_qz (last link's orientation)
//   contact force: time, pressure, force_x, force_y, force_z, force_norm
//                  [N, what the obstacle receives], contacts (count)
#include <softchain/chain/mujoco_scene.h>
#include <softchain/data/csv_table.h>

#include <Eigen/Core>

#include <vector>

namespace softchain::chain
{
  struct RampSettings
  {
    double rate            = 20e3;  // Pa/s
    double hold            = 1.5;   // s at each target
    double average         = 0.25;  // s, end of each hold averaged
    double record_interval = 0.005; // s, time-series rows (0: none)
  };

  struct SteadyContact
  {
    double          pressure; // Pa
    Eigen::Vector3d force;    // N, on the obstacle, world
    Eigen::Vector3d tip;      // m, the site "tip", mean over the same window
  };

  class PressureRampSimulation
  {
  public:
    PressureRampSimulation(MujocoScene &scene, RampSettings settings = {});

    // Ramps through `targets` (increasing, positive, within the MJCF's
    // pressure tables: else data::InputError naming the pressure) and
    // returns the steady contact force at each.
    std::vector<SteadyContact> run(const std::vector<double> &targets);

    const data::CsvTable &joint_angles() const { return joint_angles_; }
    const data::CsvTable &tip_pose() const { return tip_pose_; }
    const data::CsvTable &contact_force() const { return contact_force_; }
    double                simulated_time() const { return scene_.data()->time; }

  private:
    void check(const std::vector<double> &targets) const;
    // One MuJoCo step at `pressure`; a time-series row when one is due.
    void step(double pressure);
    // The row of `angles` (time, pressure, qpos at the step's start).
    void record(const std::vector<double> &angles);

    MujocoScene   &scene_;
    RampSettings   settings_;
    long           steps_per_record_;
    long           steps_ = 0;
    double         applied_pressure_ = -1; // the model's pressure (none yet: -1)
    data::CsvTable joint_angles_, tip_pose_, contact_force_;
  };
} // namespace softchain::chain
