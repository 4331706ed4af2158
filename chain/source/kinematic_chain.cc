#include <softchain/chain/kinematic_chain.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace softchain::chain
{
  namespace
  {
    // The shared convention E = Rx(psi) Ry(theta) Rz(phi) (data/joint_angles.h)
    // multiplied out, and the theta axis Rx(psi) e_y in the parent frame, from
    // one set of sines and cosines: the hot loop of every equilibrium
    // evaluation. A test checks E against data::rotation_from_angles.
    struct EulerFrame
    {
      Eigen::Matrix3d rotation;
      Eigen::Vector3d theta_axis;
      double          cos_psi, sin_psi;
      // Rx(psi) v
      Eigen::Vector3d twisted(const Eigen::Vector3d &v) const
      {
        return {v.x(), cos_psi * v.y() - sin_psi * v.z(), sin_psi * v.y() + cos_psi * v.z()};
      }
    };

    EulerFrame euler_frame(double psi, double theta, double phi)
    {
      const double cx = std::cos(psi), sx = std::sin(psi), cy = std::cos(theta),
                   sy = std::sin(theta), cz = std::cos(phi), sz = std::sin(phi);
      EulerFrame f;
      f.rotation << cy * cz, -cy * sz, sy,                          //
        cx * sz + sx * sy * cz, cx * cz - sx * sy * sz, -sx * cy, //
        sx * sz - cx * sy * cz, sx * cz + cx * sy * sz, cx * cy;
      f.theta_axis << 0.0, cx, sx;
      f.cos_psi = cx;
      f.sin_psi = sx;
      return f;
    }

    void check_order(const std::vector<Eigen::Vector3d> &joints, const Eigen::Vector3d &tip,
                     const std::string &what)
    {
      if (joints.empty())
        throw std::invalid_argument("KinematicChain: no joints");
      for (std::size_t i = 1; i < joints.size(); ++i)
        if (!(joints[i].x() > joints[i - 1].x()))
          throw std::invalid_argument("KinematicChain: " + what + " must increase strictly along x");
      if (!(tip.x() > joints.back().x()))
        throw std::invalid_argument("KinematicChain: the tip must lie beyond the last joint along x");
    }
  } // namespace

  KinematicChain::KinematicChain(std::vector<Eigen::Vector3d> joint_centres,
                                 const Eigen::Vector3d       &tip)
    : joint_centres_(std::move(joint_centres))
    , tip_(tip)
    , link_joints_(joint_centres_)
    , link_tip_(tip)
    , twist_offsets_(joint_centres_.size(), Eigen::Vector3d::Zero())
    , link_shifts_(joint_centres_.size(), Eigen::Vector3d::Zero())
    , shift_origins_(joint_centres_.size(), 0.0)
  {
    check_order(joint_centres_, tip_, "joint centres");
  }

  KinematicChain KinematicChain::with_twist_offsets(std::vector<Eigen::Vector3d> offsets) const
  {
    if (offsets.size() != joint_centres_.size())
      throw std::invalid_argument("KinematicChain: one twist offset per joint needed");
    for (const Eigen::Vector3d &o : offsets)
      if (!o.allFinite())
        throw std::invalid_argument("KinematicChain: a twist offset is not finite");
    KinematicChain chain     = *this;
    chain.twist_offsets_     = std::move(offsets);
    chain.has_twist_offsets_ = false;
    for (const Eigen::Vector3d &o : chain.twist_offsets_)
      chain.has_twist_offsets_ = chain.has_twist_offsets_ || o != Eigen::Vector3d::Zero();
    return chain;
  }

  KinematicChain KinematicChain::with_link_geometry(std::vector<Eigen::Vector3d> joints,
                                                    const Eigen::Vector3d       &tip,
                                                    const Eigen::Matrix3d       &tip_frame) const
  {
    if (joints.size() != joint_centres_.size())
      throw std::invalid_argument("KinematicChain: the link geometry needs one point per joint");
    KinematicChain chain = *this;
    chain.assign_link_geometry([&](const int i) { return joints[i]; }, tip, tip_frame);
    return chain;
  }

  void KinematicChain::check_link_order() const
  {
    check_order(link_joints_, link_tip_, "the link geometry's joints");
  }

  void KinematicChain::check_link_shift() const
  {
    for (int i = 0; i < n_joints(); ++i)
      if (!link_shifts_[i].allFinite() || link_shifts_[i].z() != 0.0 || !std::isfinite(shift_origins_[i]))
        throw std::invalid_argument("KinematicChain: joint " + std::to_string(i + 1) +
                                    "'s link shift must be finite and in the link's x-y plane");
  }

  int KinematicChain::link_of(const Eigen::Vector3d &X) const
  {
    int link = -1;
    while (link + 1 < n_joints() && joint_centres_[link + 1].x() <= X.x())
      ++link;
    return link;
  }

  ChainPose KinematicChain::rest_pose() const
  {
    ChainPose pose;
    pose.joint_positions = link_joints_;
    pose.twist_pivots    = link_joints_;
    for (int i = 0; i < n_joints(); ++i)
      pose.twist_pivots[i] += twist_offsets_[i];
    pose.bend_pivots  = link_joints_;
    pose.link_origins = link_joints_;
    pose.shift_rates.assign(n_joints(), Eigen::Vector3d::Zero());
    pose.link_rotations.assign(n_joints(), Eigen::Matrix3d::Identity());
    pose.joint_axes.assign(n_joints(), Eigen::Matrix3d::Identity());
    pose.tip_position = link_tip_;
    pose.tip_rotation = tip_frame_;
    return pose;
  }

  void KinematicChain::update_pose(const Eigen::VectorXd &q, ChainPose &pose) const
  {
    Eigen::Matrix3d parent   = Eigen::Matrix3d::Identity();
    Eigen::Vector3d position = link_joints_[0];
    for (int i = 0; i < n_joints(); ++i)
      {
        const EulerFrame frame = euler_frame(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
        if (has_twist_offsets_) // psi turns J_i about the twist pivot s_i
          {
            const Eigen::Vector3d &o = twist_offsets_[i];
            pose.twist_pivots[i]     = position + parent * o;
            position                 = pose.twist_pivots[i] - parent * frame.twisted(o);
          }
        else
          pose.twist_pivots[i] = position;
        pose.joint_positions[i] = position;
        // a_psi = R_{i-1} e_x, a_theta = R_{i-1} Rx e_y, a_phi = R_{i-1} E e_z = R_i e_z.
        pose.joint_axes[i].col(0) = parent.col(0);
        pose.joint_axes[i].col(1) = parent * frame.theta_axis;
        parent                    = parent * frame.rotation;
        pose.joint_axes[i].col(2) = parent.col(2);
        pose.link_rotations[i]  = parent;
        pose.bend_pivots[i]     = position;
        pose.shift_rates[i].setZero();
        if (has_link_shift_) // o_i = c_i + R_i g_i (phi_i - phi_i^p), pivot c_i + a_phi x R_i g_i
          {
            pose.shift_rates[i] = parent * link_shifts_[i];
            pose.bend_pivots[i] += parent.col(2).cross(pose.shift_rates[i]);
            position += pose.shift_rates[i] * (q[3 * i + 2] - shift_origins_[i]);
          }
        pose.link_origins[i] = position;
        const Eigen::Vector3d &next = i + 1 < n_joints() ? link_joints_[i + 1] : link_tip_;
        position += parent * (next - link_joints_[i]);
      }
    pose.tip_position = position;
    pose.tip_rotation = parent * tip_frame_;
  }

  Eigen::Vector3d KinematicChain::point_position(const ChainPose &pose, int link,
                                                 const Eigen::Vector3d &X) const
  {
    if (link < 0)
      return X;
    const bool             last = link + 1 == n_joints();
    const Eigen::Vector3d &end  = last ? tip_ : joint_centres_[link + 1];
    const Eigen::Vector3d  end_shift = (last ? link_tip_ : link_joints_[link + 1]) - end;
    const Eigen::Vector3d  start_shift = link_joints_[link] - joint_centres_[link];
    const double s = std::clamp((X - joint_centres_[link]).x() / (end - joint_centres_[link]).x(), 0.0, 1.0);
    return pose.link_origins[link] +
           pose.link_rotations[link] *
             (X + (1.0 - s) * start_shift + s * end_shift - link_joints_[link]);
  }
} // namespace softchain::chain
