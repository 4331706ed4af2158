#pragma once
// SampleReduction: one database sample reduced to the chain's variables by
// one method: per joint the relative angles (psi, theta, phi), the torque
// tau_i = (J^T f)_i + J_p,i p as the angles' generalised forces (the work of
// the moments about the twist point and the deformed joint centre per unit
// turn of each angle; conjugate_torque), J_p,i and the stretches.
#include <softchain/data/actuation_database.h>
#include <softchain/data/joint_angles.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/joint_geometry.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace softchain::reduction
{
  struct JointResult
  {
    data::JointAngles angles;
    // The angles from the last torque-carrying frame even where this joint
    // carries none (`angles` are then 0, passed on to the next joint).
    data::JointAngles free_angles;
    Eigen::Vector3d   torque;           // N m, generalised torques of (psi, theta, phi)
    Eigen::Vector3d   pressure_torque;  // J_p,i: N m per Pa, generalised as `torque`
    Eigen::Vector3d   stretches;        // principal stretches (M2), NaN for M1
  };

  class SampleReduction
  {
  public:
    SampleReduction(const data::SampleRecord &sample, const data::MeshRecord &mesh,
                    const JointGeometry &geometry, RotationMethod method);

    const std::string              &id() const { return id_; }
    const std::string              &role() const { return role_; }
    // Whether the sample's role is one of `roles`.
    bool has_role(const std::vector<std::string> &roles) const;
    double                          pressure() const { return pressure_; }
    // Sum of the magnitudes |f_k| of the sample's point forces (N).
    double                          force_norm() const;
    // Whether the sample passed a limit point of its forces on the way (the
    // finger buckled sideways; data::SampleRecord::force_limit).
    bool                            past_force_limit() const { return past_force_limit_; }
    const std::vector<JointResult> &joints() const { return joints_; }
    // The chain's link geometry U_1..U_n, U_T at this sample: joint and tip
    // positions at zero angles (chain/link_geometry.h); empty if the mesh
    // has no tip face.
    const std::vector<Eigen::Vector3d> &link_geometry() const { return link_geometry_; }
    // The tip face's frame in the last link's frame, as a rotation vector (rad).
    const Eigen::Vector3d &tip_frame() const { return tip_frame_; }
    // The sample's point forces (reference point, force).
    const std::vector<data::PointForce> &point_forces() const { return point_forces_; }
    // The tip's displacement that the links' own deformation adds from
    // `pressure_state` to this sample: the deformed tip minus where the
    // chain of pressure_state's links lands it when turned by this sample's
    // link rotations R_i,
    //   r = U_1 - U_1(p) + sum_i R_i [(U_i+1 - U_i) - (U_i+1(p) - U_i(p))],
    // 0 if the links are rigid between the two states (LinkComplianceFit).
    Eigen::Vector3d link_deflection_from(const SampleReduction &pressure_state) const;
    // Where the chain of `pressure_state`'s links, turned by this sample's
    // link rotations R_i, carries the point of link b that lies at y_p in
    // `pressure_state` (its offset L = R_b(p)^T (y_p - J_b(p))):
    //   U_1(p) + sum_{i<b} R_i (U_i+1(p) - U_i(p)) + R_b L.
    // This sample's deformed position of that point minus this is what the
    // joints' rotations do not carry (SkinComplianceFit).
    Eigen::Vector3d carried_from(const SampleReduction &pressure_state, std::size_t link,
                                 const Eigen::Vector3d &y_p) const;
    const Eigen::Matrix3d &link_rotation(std::size_t link) const { return link_rotations_.at(link); }
    // The deformed chord from joint 1's centre to the tip, sum_i R_i (U_i+1 - U_i).
    Eigen::Vector3d chord() const;

    // The generalised torques of the angles q from the moments about the
    // twist point and about the centre, both in the joint frame.
    static Eigen::Vector3d conjugate_torque(const data::JointAngles &q, const Eigen::Vector3d &about_twist,
                                            const Eigen::Vector3d &about_centre);

    // The link geometry of deformed joint centres J_1..J_n and tip T, link i
    // turned by R_i: U_1 = J_1, U_i+1 = U_i + R_i^T (J_i+1 - J_i) (J_n+1 = T).
    static std::vector<Eigen::Vector3d> link_points(const std::vector<Eigen::Vector3d> &deformed,
                                                    const std::vector<Eigen::Matrix3d> &link_rotations);

  private:
    std::string              id_;
    std::string              role_;
    double                   pressure_;
    bool                     past_force_limit_;
    std::vector<JointResult> joints_;
    std::vector<Eigen::Vector3d> link_geometry_;
    std::vector<Eigen::Matrix3d> link_rotations_; // R_i of link i (the last torque-carrying frame)
    std::vector<Eigen::Vector3d> joint_centres_;  // J_i, deformed
    Eigen::Vector3d              tip_frame_ = Eigen::Vector3d::Zero();
    std::vector<data::PointForce> point_forces_;
  };
} // namespace softchain::reduction
