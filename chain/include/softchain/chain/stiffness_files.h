#pragma once
// StiffnessFiles: the reduction tier's output that defines a chain, for one
// method (M1, M2) and slab half-width b = fraction * a, under
// <output_dir>/stiffness/ with label <M>_b<fraction with 2 decimals>a:
//   <label>.csv                   joint,x_ref,Jx,Jy,Jz,Sx,Sy,Sz,k_psi,k_theta,k_phi,
//                                 k_psi_fit,k_theta_fit,k_phi_fit,n_psi,n_theta,n_phi
//                                 (Sx, Sy, Sz, the twist axis point, optional)
//   <label>_kphi_vs_pressure.csv  pressure,joint,k_phi
//   <label>_kpsi_vs_pressure.csv, <label>_ktheta_vs_pressure.csv
//                                 pressure,joint,k_psi (k_theta); optional, used
//                                 when they hold more than one pressure
//   <label>_joint_law.csv         pressure,joint,k_psi,k_theta,k_phi,kappa,r,theta_0
//                                 (JointForceLaw; optional, without it or without
//                                 rows the joints are linear springs under forces)
//   <label>_pressure_torque.csv   pressure,joint,jp_x,jp_y,jp_z
//   <label>_link_geometry.csv     pressure,point,x,y,z,rx,ry,rz (LinkGeometry; optional,
//                                 without it the links are rigid between the
//                                 reference centres)
//   <label>_link_shift.csv        pressure,link,shift_x,shift_y (LinkShiftPerTurn, m/rad;
//                                 optional, without it or without rows the links
//                                 do not shift as their joints turn)
//   <label>_link_compliance.csv   pressure,compliance,samples (LinkCompliance, c in m/N;
//                                 optional, without it or without rows the links
//                                 are rigid under forces)
//   <label>_skin_compliance.csv   pressure,compliance,samples (ChainContact's skin,
//                                 c_s in m/N; optional, without it or without
//                                 rows the sections are rigid under contact)
//   <label>_skin_shear_compliance.csv  the same columns (CoulombFriction's c_t in
//                                 m/N; optional, without it or without rows the
//                                 sections are rigid under friction)
// Joints are numbered 1..n (docs/conventions.md, "Joints") and listed in that order in the
// stiffness file. Bad content (missing column, missing or misnumbered joint,
// NaN, zero or negative stiffness, NaN J_p) is an InputError naming the file
// and row (rows counted from 1 after the header line). In the k_phi(p) table
// NaN means "no value at this pressure" (the reduction's threshold) and the
// row is skipped; a joint without any value is an error.
#include <softchain/chain/chain_model.h>
#include <softchain/data/rotation_method.h>

#include <array>
#include <string>

namespace softchain::chain
{
  // Which stiffness of the table a chain uses: k at the largest load of
  // each axis (columns k_psi, k_theta, k_phi) or the least-squares fit over
  // the load set (k_psi_fit, k_theta_fit, k_phi_fit).
  enum class StiffnessColumn
  {
    value,
    fit
  };

  class StiffnessFiles
  {
  public:
    StiffnessFiles(const std::string &stiffness_directory, data::RotationMethod method,
                   double half_width_fraction);

    // "M2_b0.50a"
    static std::string label(data::RotationMethod method, double half_width_fraction);

    const std::string &stiffness_path() const { return stiffness_path_; }
    const std::string &bending_in_pressure_path() const { return bending_in_pressure_path_; }
    const std::string &pressure_torque_path() const { return pressure_torque_path_; }
    const std::string &link_geometry_path() const { return link_geometry_path_; }
    const std::string &link_shift_path() const { return link_shift_path_; }
    const std::string &link_compliance_path() const { return link_compliance_path_; }
    const std::string &joint_law_path() const { return joint_law_path_; }
    // k_psi(p) (axis 0) or k_theta(p) (axis 1).
    const std::string &force_in_pressure_path(int axis) const { return force_in_pressure_paths_[axis]; }
    bool               exist() const;

    // The chain of these files with the given tip point and the stiffness
    // `column`; `in_pressure` makes k_phi, J_p, the link geometry and the link
    // compliance follow their pressure tables, and gives the joints the force
    // law of the joint-law file where it has rows. A k
    // that is NaN or not positive at some joints holds them rigid
    // (`rigid_where_missing`) or is an InputError.
    // With `twist_axes`, joint i twists about the axis through its twist
    // axis point S_i (columns Sx, Sy, Sz; J_i without them) and bends about
    // J_i (KinematicChain::with_twist_offsets).
    ChainModel read_model(const std::string &name, const Eigen::Vector3d &tip,
                          StiffnessColumn column, bool in_pressure,
                          bool rigid_where_missing = true, bool twist_axes = true) const;

  private:
    std::string stiffness_path_;
    std::string bending_in_pressure_path_;
    std::array<std::string, 2> force_in_pressure_paths_; // k_psi(p), k_theta(p)
    std::string pressure_torque_path_;
    std::string link_geometry_path_;
    std::string link_shift_path_;
    std::string link_compliance_path_;
    std::string skin_compliance_path_;
    std::string skin_shear_compliance_path_;
    std::string joint_law_path_;
  };
} // namespace softchain::chain
