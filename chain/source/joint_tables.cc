// JointTables: the ChainModel of the reduction's tables.
#include <softchain/chain/joint_tables.h>

#include <stdexcept>

namespace softchain::chain
{
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
    KinematicChain chain(joint_centres, tip);
    if (!twist_points.empty())
      {
        if (twist_points.size() != joint_centres.size())
          throw std::invalid_argument("JointTables: one twist axis point per joint needed");
        std::vector<Eigen::Vector3d> offsets;
        for (std::size_t i = 0; i < twist_points.size(); ++i)
          offsets.push_back(twist_points[i] - joint_centres[i]);
        chain = chain.with_twist_offsets(offsets);
      }
    ChainModel chain_model(name, chain, std::move(stiffness_model), std::move(actuation));
    if (pressure_tables && link_geometry)
      chain_model.set_link_geometry(*link_geometry);
    if (pressure_tables && link_geometry && link_shift)
      chain_model.set_link_shift(*link_shift);
    if (pressure_tables && link_compliance)
      chain_model.set_link_compliance(LinkCompliance(*link_compliance));
    if (pressure_tables && skin_compliance)
      chain_model.set_skin_compliance(*skin_compliance);
    if (pressure_tables && skin_shear_compliance)
      chain_model.set_skin_shear_compliance(*skin_shear_compliance);
    if (pressure_tables && force_law)
      chain_model.set_force_law(force_law->completed_with(chain_model.stiffness()));
    return chain_model;
  }
} // namespace softchain::chain
