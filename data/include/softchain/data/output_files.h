#pragma once
// OutputFiles: the names of the files and folders the tiers exchange under a
// design's output directory -- the one owner of that contract, so that the
// reduction writes what the chain and the report read. The columns of each
// file are documented in docs/conventions.md ("CSV files"), the database's
// layout in data/README.md.
//
//   <output>/database.h5, database.h5.samples/   the FEM tier's database
//   <output>/vtu/                                ParaView files
//   <output>/stiffness/<label>*.csv              the reduction, per method and b (StiffnessFileSet)
//   <output>/contact/contact_forces.csv          the reduction, the contact samples
//   <output>/chain/                              the chain tier's validation
//   <output>/simulate/                           MuJoCo scenes (softchain simulate)
// where <label> is "<method>_b<b/a with two decimals>a", e.g. M2_b0.50a.
#include <softchain/data/rotation_method.h>

#include <string>

namespace softchain::data
{
  namespace folder
  {
    inline const std::string vtu       = "vtu";
    inline const std::string stiffness = "stiffness";
    inline const std::string contact   = "contact";
    inline const std::string chain     = "chain";
    inline const std::string simulate  = "simulate";
  } // namespace folder

  // "M2_b0.50a": a stiffness file set's label.
  std::string stiffness_label(RotationMethod method, double half_width_fraction);

  // The reduction's files of one label in `directory` (<output>/stiffness).
  struct StiffnessFileSet
  {
    StiffnessFileSet(const std::string &directory, const std::string &label);

    std::string table;              // <label>.csv: per joint, J, S and k
    std::string samples;            // <label>_samples.csv: angles and torques per sample and joint
    std::string kphi_vs_pressure;   // <label>_kphi_vs_pressure.csv
    std::string ktheta_vs_pressure; // <label>_ktheta_vs_pressure.csv
    std::string kpsi_vs_pressure;   // <label>_kpsi_vs_pressure.csv
    std::string joint_law;          // <label>_joint_law.csv: the force laws' knots
    std::string pressure_torque;    // <label>_pressure_torque.csv: J_p per pressure
    std::string link_geometry;      // <label>_link_geometry.csv
    std::string link_shift;         // <label>_link_shift.csv: the links' shift per in-plane turn
    std::string link_compliance;    // <label>_link_compliance.csv
    std::string skin_compliance;    // <label>_skin_compliance.csv
    std::string skin_shear_compliance; // <label>_skin_shear_compliance.csv
  };

  // <output>/contact/contact_forces.csv
  std::string contact_forces_file(const std::string &output_directory);

  // The chain tier's files in <output>/chain.
  struct ChainFileSet
  {
    explicit ChainFileSet(const std::string &output_directory);

    std::string directory;          // <output>/chain
    std::string validation;         // validation.csv: per sample and model
    std::string validation_summary; // validation_summary.csv: per model and role
    std::string validation_plot;    // validation.png
    std::string chain_poses;        // chain_poses.csv: the chains' joints and tips
    std::string fem_tip_poses;      // fem_tip_poses.csv
    std::string protocol_torques;   // protocol_torques.csv: base torques over the protocol
    std::string protocol_summary;   // protocol_summary.csv
    std::string protocol_plot;      // protocol_torques.png
    std::string protocol_plot_script; // protocol_torques.gp: gnuplot's script of it
    std::string mjcf;               // finger.xml (softchain chain --export-mjcf)
    std::string grasp_summary;      // grasp_summary.csv: contact samples per model
  };

  // The files of `softchain simulate` in <output>/simulate, one scene's
  // (named after its obstacle, or "free") in each run.
  struct SimulateFileSet
  {
    SimulateFileSet(const std::string &output_directory, const std::string &scene);

    std::string directory;      // <output>/simulate
    std::string scene_mjcf;     // <scene>.xml: the finger and the obstacle
    std::string joint_angles;   // <scene>_joint_angles.csv: time series
    std::string tip_pose;       // <scene>_tip_pose.csv: time series
    std::string contact_force;  // <scene>_contact_force.csv: time series
    std::string contact_vs_fem; // contact_vs_fem.csv: steady force per pressure against the FEM's
  };
} // namespace softchain::data
