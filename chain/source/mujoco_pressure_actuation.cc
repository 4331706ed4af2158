#include <softchain/chain/mujoco_pressure_actuation.h>
#include <softchain/data/input_error.h>

#include <string>

namespace softchain::chain
{
  namespace
  {
    const char *axis_names[3] = {"psi", "theta", "phi"};

    int id_of(const mjModel *model, const int type, const std::string &name, const char *what)
    {
      const int id = mj_name2id(model, type, name.c_str());
      if (id < 0)
        throw data::InputError("MuJoCo model: no " + std::string(what) + " '" + name +
                               "' (not a finger exported by softchain chain --export-mjcf)");
      return id;
    }

    // The values of the custom numeric field `name`.
    std::vector<double> numeric(const mjModel *model, const char *name)
    {
      const int id = mj_name2id(model, mjOBJ_NUMERIC, name);
      if (id < 0)
        throw data::InputError(std::string("MuJoCo model: no custom numeric field '") + name +
                               "': its MJCF has no pressure tables (export it again with softchain chain "
                               "--export-mjcf)");
      const mjtNum *begin = model->numeric_data + model->numeric_adr[id];
      return {begin, begin + model->numeric_size[id]};
    }

    // The field `name` as `rows` rows of equal length.
    PressureTables::Rows rows_of(const mjModel *model, const char *name, const Eigen::Index rows)
    {
      const std::vector<double> values = numeric(model, name);
      if (values.empty() || values.size() % rows != 0)
        throw data::InputError(std::string("MuJoCo model: the custom numeric field '") + name +
                               "' does not hold one row per pressure of softchain_pressure");
      const Eigen::Index columns = static_cast<Eigen::Index>(values.size()) / rows;
      return Eigen::Map<const PressureTables::Rows>(values.data(), rows, columns);
    }

    PressureTables tables_of(const mjModel *model)
    {
      std::vector<double> pressures = numeric(model, PressureTables::pressure_name);
      const Eigen::Index  m         = static_cast<Eigen::Index>(pressures.size());
      try
        {
          std::vector<double> skin;
          if (mj_name2id(model, mjOBJ_NUMERIC, PressureTables::skin_compliance_name) >= 0)
            skin = numeric(model, PressureTables::skin_compliance_name);
          return PressureTables(std::move(pressures), rows_of(model, PressureTables::stiffness_name, m),
                                rows_of(model, PressureTables::torque_per_pascal_name, m),
                                rows_of(model, PressureTables::link_points_name, m), std::move(skin));
        }
      catch (const std::invalid_argument &e)
        {
          throw data::InputError(std::string("MuJoCo model's pressure tables: ") + e.what());
        }
    }

    // The entry of joint `joint` in tendon `tendon`, -1 if it has none.
    int tendon_wrap(const mjModel *model, const int tendon, const int joint)
    {
      for (int w = model->tendon_adr[tendon]; w < model->tendon_adr[tendon] + model->tendon_num[tendon]; ++w)
        if (model->wrap_type[w] == mjWRAP_JOINT && model->wrap_objid[w] == joint)
          return w;
      return -1;
    }
  } // namespace

  MujocoPressureActuation::MujocoPressureActuation(const mjModel *model)
    : tables_(tables_of(model))
    , tip_site_(id_of(model, mjOBJ_SITE, "tip", "site"))
    , pressure_motor_(mj_name2id(model, mjOBJ_ACTUATOR, "pressure"))
  {
    const int tendon = mj_name2id(model, mjOBJ_TENDON, "pressure");
    for (int i = 0; i < tables_.n_joints(); ++i)
      {
        const std::string link = "link" + std::to_string(i + 1);
        bodies_.push_back(id_of(model, mjOBJ_BODY, link, "body"));
        capsules_.push_back(id_of(model, mjOBJ_GEOM, link, "geom"));
        sides_.push_back(mj_name2id(model, mjOBJ_GEOM, (link + "_side").c_str()));
        side_offset_.push_back(sides_.back() < 0 ? 0.0
                                                 : 0.5 * (model->geom_pos[3 * sides_.back() + 2] -
                                                          model->geom_pos[3 * capsules_.back() + 2]));
        for (int axis = 0; axis < 3; ++axis)
          {
            const int joint = id_of(model, mjOBJ_JOINT,
                                    "joint" + std::to_string(i + 1) + "_" + axis_names[axis], "hinge");
            const int dof   = model->jnt_dofadr[joint];
            const int wrap  = tendon < 0 ? -1 : tendon_wrap(model, tendon, joint);
            if (!(model->jnt_stiffness[joint] > 0.0))
              throw data::InputError("MuJoCo model: hinge joint" + std::to_string(i + 1) + "_" +
                                     axis_names[axis] + " has no spring (stiffness not positive)");
            if (tables_.turns_hinge(3 * i + axis) && (wrap < 0 || pressure_motor_ < 0))
              throw data::InputError("MuJoCo model: the pressure turns hinge joint" + std::to_string(i + 1) +
                                     "_" + axis_names[axis] +
                                     ", which the tendon and motor 'pressure' do not drive");
            hinges_.push_back({joint, dof, wrap, model->dof_damping[dof] / model->jnt_stiffness[joint]});
          }
        const int skin = mj_name2id(model, mjOBJ_JOINT, ("skin" + std::to_string(i + 1)).c_str());
        if (skin < 0)
          continue;
        if (!tables_.has_skin() || !(model->jnt_stiffness[skin] > 0.0))
          throw data::InputError("MuJoCo model: skin joint skin" + std::to_string(i + 1) +
                                 " without the custom field '" + PressureTables::skin_compliance_name +
                                 "' or without a spring");
        const int dof = model->jnt_dofadr[skin];
        skins_.push_back({skin, dof, -1, model->dof_damping[dof] / model->jnt_stiffness[skin]});
      }
  }

  void MujocoPressureActuation::apply(const double pressure, mjModel *model, mjData *data) const
  {
    const Eigen::VectorXd k = tables_.stiffness(pressure), jp = tables_.torque_per_pascal(pressure);
    set_links(tables_.link_points(pressure), model);
    for (std::size_t j = 0; j < hinges_.size(); ++j)
      {
        const Hinge &h                = hinges_[j];
        model->jnt_stiffness[h.joint] = k[j];
        model->dof_damping[h.dof]     = h.damping_time * k[j];
        if (h.tendon_wrap >= 0)
          model->wrap_prm[h.tendon_wrap] = jp[j];
      }
    for (const Hinge &s : skins_)
      {
        model->jnt_stiffness[s.joint] = 1.0 / tables_.skin_compliance(pressure);
        model->dof_damping[s.dof]     = s.damping_time * model->jnt_stiffness[s.joint];
      }
    if (pressure_motor_ >= 0)
      data->ctrl[pressure_motor_] = pressure;
  }

  // Body i at U_i - U_{i-1} in its parent (U_0 = the world origin), its
  // capsule from its origin to the next joint (the tip for the last link),
  // the tip site at U_T - U_n.
  void MujocoPressureActuation::set_links(const Eigen::VectorXd &points, mjModel *model) const
  {
    const int       n        = tables_.n_joints();
    Eigen::Vector3d previous = Eigen::Vector3d::Zero(); // U_0
    for (int i = 0; i < n; ++i)
      {
        const Eigen::Vector3d joint = points.segment<3>(3 * i);
        const Eigen::Vector3d link  = points.segment<3>(3 * (i + 1)) - joint;
        Eigen::Map<Eigen::Vector3d>(model->body_pos + 3 * bodies_[i]) = joint - previous;
        previous                                                     = joint;
        for (const int g : {capsules_[i], sides_[i]})
          {
            if (g < 0)
              continue;
            const double side = g == sides_[i] ? side_offset_[i] : -side_offset_[i];
            Eigen::Map<Eigen::Vector3d>(model->geom_pos + 3 * g) = 0.5 * link + Eigen::Vector3d(0.0, 0.0, side);
            mju_quatZ2Vec(model->geom_quat + 4 * g, link.data());
            model->geom_size[3 * g + 1] = 0.5 * link.norm();
            model->geom_rbound[g]       = model->geom_size[3 * g] + model->geom_size[3 * g + 1];
          }
      }
    Eigen::Map<Eigen::Vector3d>(model->site_pos + 3 * tip_site_) =
      points.segment<3>(3 * n) - points.segment<3>(3 * (n - 1));
  }
} // namespace softchain::chain
