#include <softchain/chain/link_wrench_stiffness.h>

#include <algorithm>

namespace softchain::chain
{
  void LinkWrenchStiffness::reset(const int n_links)
  {
    stiffness_.assign(n_links, Matrix6d::Zero());
    force_.assign(n_links, Vector6d::Zero());
    last_stiff_ = last_force_ = -1;
  }

  void LinkWrenchStiffness::add_row(const int link, const Vector6d &g, const double weight)
  {
    stiffness_[link].noalias() += weight * g * g.transpose();
    last_stiff_ = std::max(last_stiff_, link);
  }

  void LinkWrenchStiffness::add_force(const int link, const Vector6d &g, const double scale)
  {
    force_[link] += scale * g;
    last_force_ = std::max(last_force_, link);
  }

  // xi_{i,alpha} = (a, p x a), p = s_i for psi (alpha = 0), c_i otherwise.
  void LinkWrenchStiffness::joint_twists(const ChainPose &pose) const
  {
    const auto n = static_cast<Eigen::Index>(pose.joint_axes.size());
    twists_.resize(6, 3 * n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (int alpha = 0; alpha < 3; ++alpha)
        {
          const Eigen::Vector3d  a     = pose.joint_axes[i].col(alpha);
          const Eigen::Vector3d &pivot = pose.pivot(i, alpha);
          twists_.col(3 * i + alpha) << a, pivot.cross(a);
        }
  }

  // Row block j, columns of the joints up to j: (S_j Xi_j)^T Xi_{0..j};
  // mirrored, the blocks left of the diagonal also above it (the diagonal
  // blocks Xi_j^T S_j Xi_j are symmetric).
  void LinkWrenchStiffness::add_blocks(const ChainPose &pose, Eigen::MatrixXd &dense, const bool mirror) const
  {
    if (last_stiff_ < 0)
      return;
    joint_twists(pose);
    Matrix6d S = Matrix6d::Zero();
    for (int j = last_stiff_; j >= 0; --j)
      {
        S += stiffness_[j];
        const Eigen::Matrix<double, 6, 3> W = S * twists_.middleCols<3>(3 * j);
        dense.block(3 * j, 0, 3, 3 * j + 3).noalias() += W.transpose() * twists_.leftCols(3 * j + 3);
        if (mirror)
          dense.block(0, 3 * j, 3 * j, 3).noalias() += twists_.leftCols(3 * j).transpose() * W;
      }
  }

  void LinkWrenchStiffness::add_to_lower(const ChainPose &pose, Eigen::MatrixXd &dense) const
  {
    add_blocks(pose, dense, false);
  }

  void LinkWrenchStiffness::add_to(const ChainPose &pose, Eigen::MatrixXd &dense) const
  {
    add_blocks(pose, dense, true);
  }

  void LinkWrenchStiffness::add_generalised_force(const ChainPose &pose, Eigen::VectorXd &generalised) const
  {
    if (last_force_ < 0)
      return;
    joint_twists(pose);
    Vector6d h = Vector6d::Zero();
    for (int i = last_force_; i >= 0; --i)
      {
        h += force_[i];
        generalised.segment<3>(3 * i).noalias() += twists_.middleCols<3>(3 * i).transpose() * h;
      }
  }
} // namespace softchain::chain
