#include <softchain/chain/kinematic_chain.h>

#include <cmath>
#include <stdexcept>

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
      return f;
    }
  } // namespace

  KinematicChain::KinematicChain(std::vector<Eigen::Vector3d> joint_centres,
                                 const Eigen::Vector3d       &tip)
    : joint_centres_(std::move(joint_centres))
    , tip_(tip)
  {
    if (joint_centres_.empty())
      throw std::invalid_argument("KinematicChain: no joints");
    for (std::size_t i = 1; i < joint_centres_.size(); ++i)
      if (!(joint_centres_[i].x() > joint_centres_[i - 1].x()))
        throw std::invalid_argument(
          "KinematicChain: joint centres must increase strictly along x");
    if (!(tip_.x() > joint_centres_.back().x()))
      throw std::invalid_argument(
        "KinematicChain: the tip must lie beyond the last joint along x");
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
    pose.joint_positions = joint_centres_;
    pose.link_rotations.assign(n_joints(), Eigen::Matrix3d::Identity());
    pose.joint_axes.assign(n_joints(), Eigen::Matrix3d::Identity());
    pose.tip_position = tip_;
    return pose;
  }

  void KinematicChain::update_pose(const Eigen::VectorXd &q, ChainPose &pose) const
  {
    Eigen::Matrix3d parent   = Eigen::Matrix3d::Identity();
    Eigen::Vector3d position = joint_centres_[0];
    for (int i = 0; i < n_joints(); ++i)
      {
        const EulerFrame frame  = euler_frame(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
        pose.joint_positions[i] = position;
        // a_psi = R_{i-1} e_x, a_theta = R_{i-1} Rx e_y, a_phi = R_{i-1} E e_z = R_i e_z.
        pose.joint_axes[i].col(0) = parent.col(0);
        pose.joint_axes[i].col(1) = parent * frame.theta_axis;
        parent                    = parent * frame.rotation;
        pose.joint_axes[i].col(2) = parent.col(2);
        pose.link_rotations[i]  = parent;
        const Eigen::Vector3d &next = i + 1 < n_joints() ? joint_centres_[i + 1] : tip_;
        position += parent * (next - joint_centres_[i]);
      }
    pose.tip_position = position;
  }

  Eigen::Vector3d KinematicChain::point_position(const ChainPose &pose, int link,
                                                 const Eigen::Vector3d &X) const
  {
    if (link < 0)
      return X;
    return pose.joint_positions[link] +
           pose.link_rotations[link] * (X - joint_centres_[link]);
  }
} // namespace softchain::chain
