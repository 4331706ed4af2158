#include <softchain/chain/pressure_ramp_simulation.h>
#include <softchain/data/input_error.h>

#include <cmath>
#include <string>

namespace softchain::chain
{
  namespace
  {
    std::vector<std::string> hinge_columns(const mjModel *model)
    {
      std::vector<std::string> columns{"time", "pressure"};
      for (int j = 0; j < model->njnt; ++j)
        columns.emplace_back(mj_id2name(model, mjOBJ_JOINT, j));
      return columns;
    }
  } // namespace

  PressureRampSimulation::PressureRampSimulation(MujocoScene &scene, const RampSettings settings)
    : scene_(scene)
    , settings_(settings)
    , steps_per_record_(settings.record_interval > 0
                          ? std::max(1L, std::lround(settings.record_interval / scene.model()->opt.timestep))
                          : 0)
    , joint_angles_(hinge_columns(scene.model()))
    , tip_pose_({"time", "pressure", "tip_x", "tip_y", "tip_z", "tip_qw", "tip_qx", "tip_qy", "tip_qz"})
    , contact_force_({"time", "pressure", "force_x", "force_y", "force_z", "force_norm", "contacts"})
  {}

  void PressureRampSimulation::check(const std::vector<double> &targets) const
  {
    const double top = scene_.actuation().tables().pressures().back();
    for (std::size_t t = 0; t < targets.size(); ++t)
      if (!(targets[t] > (t == 0 ? 0.0 : targets[t - 1])) || targets[t] > top)
        throw data::InputError("pressure ramp: target " + std::to_string(targets[t]) +
                               " Pa is not above the previous one or beyond the MJCF's pressure tables "
                               "(0 to " + std::to_string(top) + " Pa)");
  }

  std::vector<SteadyContact> PressureRampSimulation::run(const std::vector<double> &targets)
  {
    check(targets);
    const double               dt = scene_.model()->opt.timestep;
    const long                 hold_steps = std::lround(settings_.hold / dt);
    const long                 mean_steps = std::max(1L, std::lround(settings_.average / dt));
    std::vector<SteadyContact> steady;
    double                     from = 0.0;
    for (const double target : targets)
      {
        const long ramp_steps = std::lround((target - from) / settings_.rate / dt);
        for (long s = 1; s <= ramp_steps; ++s)
          step(from + (target - from) * s / ramp_steps);
        Eigen::Vector3d force = Eigen::Vector3d::Zero(), tip = Eigen::Vector3d::Zero();
        for (long s = 0; s < hold_steps; ++s)
          {
            step(target);
            if (s >= hold_steps - mean_steps)
              {
                force += scene_.obstacle_force();
                tip += scene_.tip_position();
              }
          }
        const double n = static_cast<double>(std::min(mean_steps, hold_steps));
        steady.push_back({target, force / n, tip / n});
        from = target;
      }
    return steady;
  }

  void PressureRampSimulation::step(const double pressure)
  {
    mjData    *d   = scene_.data();
    const bool due = steps_per_record_ > 0 && steps_++ % steps_per_record_ == 0;
    // mj_step leaves the poses and contacts of its forward pass at the
    // step's start time in mjData, the angles of its end: the row takes
    // the angles before the step, so that all its columns are of one time.
    std::vector<double> angles;
    if (due)
      {
        angles = {d->time, pressure};
        angles.insert(angles.end(), d->qpos, d->qpos + scene_.model()->nq);
      }
    if (pressure != applied_pressure_) // a hold keeps the model's fields
      scene_.actuation().apply(pressure, scene_.model(), d);
    applied_pressure_ = pressure;
    mj_step(scene_.model(), d);
    if (due)
      record(angles);
  }

  void PressureRampSimulation::record(const std::vector<double> &angles)
  {
    const double time = angles[0], pressure = angles[1];
    joint_angles_.add_row(angles);
    const Eigen::Vector3d tip = scene_.tip_position();
    const Eigen::Vector4d q   = scene_.tip_orientation();
    tip_pose_.add_row(std::vector<double>{time, pressure, tip.x(), tip.y(), tip.z(), q[0], q[1], q[2], q[3]});
    const Eigen::Vector3d f = scene_.obstacle_force();
    contact_force_.add_row(std::vector<double>{time, pressure, f.x(), f.y(), f.z(), f.norm(),
                                               static_cast<double>(scene_.data()->ncon)});
  }
} // namespace softchain::chain
