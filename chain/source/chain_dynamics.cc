#include <softchain/chain/chain_dynamics.h>

#include <Eigen/LU>

#include <algorithm>

#include <stdexcept>

namespace softchain::chain
{
  ChainDynamics::ChainDynamics(const ChainModel &model, std::vector<double> link_masses,
                               Eigen::VectorXd damping)
    : model_(model)
    , statics_(model)
    , masses_(std::move(link_masses))
    , damping_(std::move(damping))
    , angles_(Eigen::VectorXd::Zero(model.chain().n_angles()))
    , velocities_(Eigen::VectorXd::Zero(model.chain().n_angles()))
  {
    const KinematicChain &chain = model.chain();
    if (static_cast<int>(masses_.size()) != chain.n_joints() || damping_.size() != chain.n_angles() ||
        *std::min_element(masses_.begin(), masses_.end()) < 0.0 || damping_.minCoeff() < 0.0)
      throw std::invalid_argument("ChainDynamics: need a mass >= 0 per link and a damping >= 0 per angle");
    for (int b = 0; b < chain.n_joints(); ++b)
      {
        const Eigen::Vector3d &end = b + 1 < chain.n_joints() ? chain.joint_centre(b + 1) : chain.tip();
        mass_points_.push_back(0.5 * (chain.joint_centre(b) + end));
      }
  }

  void ChainDynamics::set_state(const Eigen::VectorXd &angles, const Eigen::VectorXd &velocities)
  {
    if (angles.size() != angles_.size() || velocities.size() != velocities_.size())
      throw std::invalid_argument("ChainDynamics: 3 angles and 3 velocities per joint needed");
    angles_     = angles;
    velocities_ = velocities;
  }

  Eigen::MatrixXd ChainDynamics::mass_matrix() const
  {
    const ChainPose &pose = statics_.pose();
    const int        n    = model_.chain().n_joints();
    Eigen::MatrixXd  m    = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    Eigen::MatrixXd  g(3, 3 * n);
    for (int b = 0; b < n; ++b)
      {
        const Eigen::Vector3d x = statics_.chain().point_position(pose, b, mass_points_[b]);
        g.setZero();
        for (int j = 0; j <= b; ++j)
          for (int alpha = 0; alpha < 3; ++alpha)
            g.col(3 * j + alpha) = pose.joint_axes[j].col(alpha).cross(x - pose.pivot(j, alpha));
        m += masses_[b] * g.transpose() * g;
      }
    return m;
  }

  void ChainDynamics::step(double h)
  {
    if (!(h > 0.0))
      throw std::invalid_argument("ChainDynamics: the time step must be positive");
    const Eigen::VectorXd residual = statics_.residual(angles_);
    const Eigen::MatrixXd tangent  = statics_.tangent(angles_); // leaves the pose at angles_
    const Eigen::MatrixXd mass     = mass_matrix();
    const Eigen::MatrixXd system =
      mass + Eigen::MatrixXd(h * damping_.asDiagonal()) + h * h * tangent;
    velocities_ = system.partialPivLu().solve(mass * velocities_ - h * residual);
    angles_ += h * velocities_;
  }
} // namespace softchain::chain
