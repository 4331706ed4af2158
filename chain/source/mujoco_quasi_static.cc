#include <softchain/chain/mujoco_quasi_static.h>
#include <softchain/chain/mujoco_model_file.h>
#include <softchain/data/input_error.h>

#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    constexpr double rest_speed = 1e-11; // rad/s
    constexpr double rest_angle = 1e-12; // rad, unbalanced torque / k
    constexpr long   max_steps  = 2000000;
  } // namespace

  MujocoQuasiStatic::MujocoQuasiStatic(const std::string &path, const Pressure pressure)
    : model_(load_mujoco_model(path))
    , data_(mj_makeData(model_))
    , tip_site_(mj_name2id(model_, mjOBJ_SITE, "tip"))
    , pressure_motor_(mj_name2id(model_, mjOBJ_ACTUATOR, "pressure"))
  {
    try
      {
        if (tip_site_ < 0)
          throw data::InputError("MuJoCo model '" + path + "' has no site 'tip'");
        if (pressure == Pressure::tables)
          actuation_.emplace(model_);
      }
    catch (...)
      {
        mj_deleteData(data_);
        mj_deleteModel(model_);
        throw;
      }
    mju_zero3(model_->opt.gravity);
  }

  MujocoQuasiStatic::~MujocoQuasiStatic()
  {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }

  // The dead tip force as MuJoCo's applied wrench on the last body (at its
  // centre of mass): force f and torque (tip - com) x f.
  void MujocoQuasiStatic::apply_tip_force(const Eigen::Vector3d &force)
  {
    const int                                 last = model_->site_bodyid[tip_site_];
    const Eigen::Map<const Eigen::Vector3d>   at(data_->site_xpos + 3 * tip_site_), com(data_->xipos + 3 * last);
    Eigen::Map<Eigen::Matrix<double, 6, 1>>(data_->xfrc_applied + 6 * last) << force, (at - com).cross(force);
  }

  bool MujocoQuasiStatic::at_rest() const
  {
    for (int dof = 0; dof < model_->nv; ++dof)
      if (std::abs(data_->qvel[dof]) >= rest_speed ||
          std::abs(data_->qfrc_smooth[dof]) > rest_angle * model_->jnt_stiffness[model_->dof_jntid[dof]])
        return false;
    return true;
  }

  MujocoRestPose MujocoQuasiStatic::rest_pose(const double pressure, const Eigen::Vector3d &tip_force)
  {
    if (actuation_)
      actuation_->apply(pressure, model_, data_);
    else if (pressure_motor_ >= 0)
      data_->ctrl[pressure_motor_] = pressure;
    long steps = 0;
    for (mj_forward(model_, data_); steps < max_steps; ++steps)
      {
        apply_tip_force(tip_force);
        mj_step(model_, data_);
        if (steps > 10 && at_rest())
          break;
      }
    if (steps == max_steps)
      throw std::runtime_error("MuJoCo is not at rest after " + std::to_string(max_steps) + " steps at " +
                               std::to_string(pressure) + " Pa");
    mj_forward(model_, data_);
    return {Eigen::Map<const Eigen::VectorXd>(data_->qpos, model_->nq),
            Eigen::Map<const Eigen::Vector3d>(data_->site_xpos + 3 * tip_site_), steps};
  }
} // namespace softchain::chain
