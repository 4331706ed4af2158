#include <softchain/data/output_files.h>

#include <cstdio>

namespace softchain::data
{
  std::string stiffness_label(const RotationMethod method, const double half_width_fraction)
  {
    char fraction[32];
    std::snprintf(fraction, sizeof(fraction), "%.2f", half_width_fraction);
    return method_name(method) + "_b" + fraction + "a";
  }

  StiffnessFileSet::StiffnessFileSet(const std::string &directory, const std::string &label)
  {
    const std::string stem = directory + "/" + label;
    table              = stem + ".csv";
    samples            = stem + "_samples.csv";
    kphi_vs_pressure   = stem + "_kphi_vs_pressure.csv";
    ktheta_vs_pressure = stem + "_ktheta_vs_pressure.csv";
    kpsi_vs_pressure   = stem + "_kpsi_vs_pressure.csv";
    joint_law          = stem + "_joint_law.csv";
    pressure_torque    = stem + "_pressure_torque.csv";
    link_geometry      = stem + "_link_geometry.csv";
    link_shift         = stem + "_link_shift.csv";
    link_compliance    = stem + "_link_compliance.csv";
    skin_compliance    = stem + "_skin_compliance.csv";
    skin_shear_compliance = stem + "_skin_shear_compliance.csv";
  }

  std::string contact_forces_file(const std::string &output_directory)
  {
    return output_directory + "/" + folder::contact + "/contact_forces.csv";
  }

  ChainFileSet::ChainFileSet(const std::string &output_directory)
    : directory(output_directory + "/" + folder::chain)
    , validation(directory + "/validation.csv")
    , validation_summary(directory + "/validation_summary.csv")
    , validation_plot(directory + "/validation.png")
    , chain_poses(directory + "/chain_poses.csv")
    , fem_tip_poses(directory + "/fem_tip_poses.csv")
    , protocol_torques(directory + "/protocol_torques.csv")
    , protocol_summary(directory + "/protocol_summary.csv")
    , protocol_plot(directory + "/protocol_torques.png")
    , protocol_plot_script(directory + "/protocol_torques.gp")
    , mjcf(directory + "/finger.xml")
    , grasp_summary(directory + "/grasp_summary.csv")
  {}

  SimulateFileSet::SimulateFileSet(const std::string &output_directory, const std::string &scene)
    : directory(output_directory + "/" + folder::simulate)
    , scene_mjcf(directory + "/" + scene + ".xml")
    , joint_angles(directory + "/" + scene + "_joint_angles.csv")
    , tip_pose(directory + "/" + scene + "_tip_pose.csv")
    , contact_force(directory + "/" + scene + "_contact_force.csv")
    , contact_vs_fem(directory + "/contact_vs_fem.csv")
  {}
} // namespace softchain::data
