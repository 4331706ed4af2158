// JointTables: twist joints and the ChainModel of the reduction's tables.
#include <softchain/chain/joint_tables.h>

namespace softchain::chain
{
  namespace
  {
    PiecewiseLinear constant(const double value)
    {
      return PiecewiseLinear({0.0}, {value});
    }
  } // namespace

  JointTables JointTables::with_twist_joints(const std::vector<Eigen::Vector3d> &twist_points,
                                             const Eigen::Vector3d              &rigid) const
  {
    bool any = false;
    for (std::size_t i = 0; i < twist_points.size(); ++i)
      any = any || twist_points[i] != joint_centres[i];
    if (!any)
      return *this;
    JointTables                  pairs;
    std::vector<Eigen::Vector3d> offsets; // twist joint from its bending joint
    for (std::size_t i = 0; i < twist_points.size(); ++i)
      {
        offsets.push_back(twist_points[i] - Eigen::Vector3d(1e-9, 0, 0) - joint_centres[i]);
        pairs.joint_centres.push_back(joint_centres[i] + offsets.back());
        pairs.joint_centres.push_back(joint_centres[i]);
        pairs.twist_joints.insert(pairs.twist_joints.end(), {true, false});
        const Eigen::Vector3d &k = stiffness[i];
        pairs.stiffness.emplace_back(k[0], rigid[1], rigid[2]);
        pairs.stiffness.emplace_back(rigid[0], k[1], k[2]);
        for (int axis = 0; axis < 3; ++axis)
          if (!k_in_pressure[axis].empty())
            {
              const PiecewiseLinear &table = k_in_pressure[axis][i];
              pairs.k_in_pressure[axis].push_back(axis == 0 ? table : constant(rigid[axis]));
              pairs.k_in_pressure[axis].push_back(axis == 0 ? constant(rigid[axis]) : table);
            }
        for (int axis = 0; axis < 3; ++axis)
          pairs.pressure_torque.push_back(axis == 0 ? pressure_torque[3 * i] : constant(0.0));
        for (int axis = 0; axis < 3; ++axis)
          pairs.pressure_torque.push_back(axis == 0 ? constant(0.0) : pressure_torque[3 * i + axis]);
      }
    if (link_geometry)
      pairs.link_geometry = link_geometry->with_twist_joints(offsets);
    return pairs;
  }

  ChainModel JointTables::model(const std::string &name, const Eigen::Vector3d &tip,
                                const bool pressure_tables) const
  {
    JointStiffness stiffness_model(stiffness);
    for (int axis = 0; axis < 3; ++axis)
      if (!k_in_pressure[axis].empty())
        stiffness_model.set_in_pressure(axis, k_in_pressure[axis]);
    Eigen::VectorXd rest(pressure_torque.size());
    for (std::size_t j = 0; j < pressure_torque.size(); ++j)
      rest[j] = pressure_torque[j](0.0);
    PressureActuation actuation(rest);
    if (pressure_tables)
      actuation.set_torque_in_pressure(pressure_torque);
    ChainModel chain_model(name, KinematicChain(joint_centres, tip), std::move(stiffness_model),
                           std::move(actuation));
    if (!twist_joints.empty())
      chain_model.set_twist_joints(twist_joints);
    if (pressure_tables && link_geometry)
      chain_model.set_link_geometry(*link_geometry);
    return chain_model;
  }
} // namespace softchain::chain
