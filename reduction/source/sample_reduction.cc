// SampleReduction: angles and torques tau_i = (J^T f)_i + J_p,i p per joint.
#include <softchain/reduction/external_force_torque.h>
#include <softchain/reduction/joint_frames.h>
#include <softchain/reduction/pressure_torque.h>
#include <softchain/reduction/sample_reduction.h>
#include <softchain/data/tip_pose_fit.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softchain::reduction
{
  SampleReduction::SampleReduction(const data::SampleRecord &sample, const data::MeshRecord &mesh,
                                   const JointGeometry &geometry, RotationMethod method)
    : id_(sample.id)
    , role_(sample.actuation.role)
    , pressure_(sample.actuation.pressure)
    , past_force_limit_(std::isfinite(sample.force_limit))
    , point_forces_(sample.actuation.point_forces)
  {
    const JointFrames frames(method, geometry.slabs(), geometry.reference_points(),
                             geometry.points(sample.x), sample.id);
    const PressureTorque      pressure_torque(mesh.cavity_triangles, sample.x);
    const ExternalForceTorque external(sample);
    double                       largest_torque = 0;
    std::vector<Eigen::Vector3d> centres;
    // Per joint, in its frame: the moments about the twist point S_i (for
    // psi) and about the centre J_i (for theta, phi), of the loads and per
    // pascal of the pressure; turned into the angles' generalised torques
    // once the angles are known (conjugate_torque).
    std::vector<Eigen::Vector3d> about_twist, pressure_about_twist;
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        const JointFrame     &frame  = frames[i];
        const Eigen::Vector3d centre = geometry.deformed_centre(i, frames, sample.x);
        centres.push_back(centre);
        JointResult           joint;
        const Eigen::Vector3d normal = geometry.section_normal(i, frames);
        joint.pressure_torque = pressure_torque.per_pascal(centre, frame.rotation, normal);
        joint.torque = external.about(geometry.x_joint(i), centre, frame.rotation) +
                       joint.pressure_torque * pressure_;
        about_twist.push_back(joint.torque);
        pressure_about_twist.push_back(joint.pressure_torque);
        if (geometry.twist_offset() != 0.0)
          {
            const Eigen::Vector3d twist_point = geometry.deformed_twist_point(i, frames, sample.x);
            pressure_about_twist.back() =
              pressure_torque.per_pascal_about(twist_point, centre, frame.rotation, normal);
            about_twist.back() = external.about(geometry.x_joint(i), twist_point, frame.rotation) +
                                 pressure_about_twist.back() * pressure_;
          }
        joint.stretches = frame.stretches;
        largest_torque  = std::max(largest_torque, joint.torque.norm());
        joints_.push_back(joint);
      }
    // A joint that transmits no torque cannot be a spring: the chain holds it
    // rigid (e.g. P10's joint 1 in the solid base fill, distal to which lies
    // the whole closed cavity, whose pressure has no net moment, while the
    // slab of its link reaches into the bending part). Its rotation goes to
    // the next joint: angles are measured from the last frame that carries
    // torque. "No torque" is |tau_i| <= 1e-6 of the sample's largest (the
    // geometric torques are exact up to round-off, 1e-12 relative).
    std::vector<Eigen::Matrix3d> link_rotations;
    Eigen::Matrix3d              parent = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i < frames.size(); ++i)
      {
        JointResult &joint          = joints_[i];
        const bool   carries_torque = joint.torque.norm() > 1e-6 * largest_torque;
        joint.free_angles = data::angles_from_rotation(parent.transpose() * frames[i].rotation);
        joint.angles      = carries_torque ? joint.free_angles : data::JointAngles{};
        joint.torque      = conjugate_torque(joint.free_angles, about_twist[i], joint.torque);
        joint.pressure_torque =
          conjugate_torque(joint.free_angles, pressure_about_twist[i], joint.pressure_torque);
        if (carries_torque)
          parent = frames[i].rotation;
        link_rotations.push_back(parent);
      }
    link_rotations_ = link_rotations;
    joint_centres_  = centres;
    if (!mesh.tip_nodes.empty())
      {
        const data::TipPose tip =
          data::TipPoseFit::of_mesh(mesh, sample.id).fit(data::select_nodes(sample.x, mesh.tip_nodes));
        centres.push_back(tip.position);
        link_geometry_ = link_points(centres, link_rotations);
        const Eigen::AngleAxisd tip_frame(link_rotations.back().transpose() * tip.rotation);
        tip_frame_ = tip_frame.angle() * tip_frame.axis();
      }
  }

  // The generalised torques of the Euler angles q = (psi, theta, phi) of
  // R = Rx(psi) Ry(theta) Rz(phi), from the moments in the joint's (distal)
  // frame. The angles turn about the axes a_psi = e_x, a_theta = Rx(psi) e_y
  // and a_phi = Rx(psi) Ry(theta) e_z of the proximal frame, so a moment M
  // (distal components m = R^T M) does the work M . a dq, and
  //   Q_psi = (R^T e_x) . m_S,   Q_theta = (Rz(phi)^T e_y) . m_J,   Q_phi = m_J,z
  // (m_S about the twist point, m_J about the centre): the torques that the
  // chain's springs balance (chain/README.md, "Equilibrium"). On a joint
  // bent in its plane by phi they differ from the frame's components at
  // first order: Q_psi = cos(phi) m_x - sin(phi) m_y at theta = 0, so a
  // lateral moment twists a bent joint.
  Eigen::Vector3d SampleReduction::conjugate_torque(const data::JointAngles &q,
                                                    const Eigen::Vector3d  &about_twist,
                                                    const Eigen::Vector3d  &about_centre)
  {
    const Eigen::Matrix3d R = data::rotation_from_angles(q);
    return {R.row(0).dot(about_twist), std::sin(q.phi) * about_centre.x() + std::cos(q.phi) * about_centre.y(),
            about_centre.z()};
  }

  Eigen::Vector3d SampleReduction::carried_from(const SampleReduction &pressure_state, const std::size_t link,
                                                const Eigen::Vector3d &y_p) const
  {
    const auto &U_p = pressure_state.link_geometry_;
    if (U_p.size() != link_geometry_.size() || link + 1 >= U_p.size())
      throw std::invalid_argument("SampleReduction: samples " + id_ + " and " + pressure_state.id_ +
                                  " have no link geometry of the same joints");
    Eigen::Vector3d x = U_p.front();
    for (std::size_t i = 0; i < link; ++i)
      x += link_rotations_[i] * (U_p[i + 1] - U_p[i]);
    const Eigen::Vector3d offset =
      pressure_state.link_rotations_[link].transpose() * (y_p - pressure_state.joint_centres_[link]);
    return x + link_rotations_[link] * offset;
  }

  // The chain's link geometry at this sample (chain/link_geometry.h): the
  // joint and tip positions U at zero angles from which the chain, its link
  // i turned by R_i (the rotation the sample's angles give it), lands on the
  // deformed joint centres J_i and the tip centroid T:
  //   U_1 = J_1,   U_i+1 = U_i + R_i^T (J_i+1 - J_i)   (J_n+1 = T),
  // and the tip face's frame R_T (TipPoseFit) in the last link's frame,
  // Q_T = R_n^T R_T, kept as its rotation vector.
  std::vector<Eigen::Vector3d> SampleReduction::link_points(const std::vector<Eigen::Vector3d> &deformed,
                                                            const std::vector<Eigen::Matrix3d> &link_rotations)
  {
    std::vector<Eigen::Vector3d> points{deformed.front()};
    for (std::size_t i = 0; i + 1 < deformed.size(); ++i)
      points.push_back(points.back() + link_rotations[i].transpose() * (deformed[i + 1] - deformed[i]));
    return points;
  }

  double SampleReduction::force_norm() const
  {
    double sum = 0.0;
    for (const auto &f : point_forces_)
      sum += data::vector_of(f.force).norm();
    return sum;
  }

  Eigen::Vector3d SampleReduction::link_deflection_from(const SampleReduction &pressure_state) const
  {
    const auto &U = link_geometry_, &U_p = pressure_state.link_geometry_;
    if (U.empty() || U.size() != U_p.size())
      throw std::invalid_argument("SampleReduction: samples " + id_ + " and " + pressure_state.id_ +
                                  " have no link geometry of the same joints");
    Eigen::Vector3d r = U.front() - U_p.front();
    for (std::size_t i = 0; i + 1 < U.size(); ++i)
      r += link_rotations_[i] * ((U[i + 1] - U[i]) - (U_p[i + 1] - U_p[i]));
    return r;
  }

  bool SampleReduction::has_role(const std::vector<std::string> &roles) const
  {
    return std::find(roles.begin(), roles.end(), role_) != roles.end();
  }

  Eigen::Vector3d SampleReduction::chord() const
  {
    Eigen::Vector3d chord = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 1 < link_geometry_.size(); ++i)
      chord += link_rotations_[i] * (link_geometry_[i + 1] - link_geometry_[i]);
    return chord;
  }
} // namespace softchain::reduction
