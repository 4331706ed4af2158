#include <softchain/chain/chain_tangent.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace softchain::chain
{
  ChainTangent::ChainTangent(int n_joints)
    : diagonal_(n_joints, Eigen::Matrix3d::Zero())
    , coupling_(n_joints, Eigen::Matrix3d::Zero())
    , axes_(n_joints, Eigen::Matrix3d::Identity())
    , inverse_pivots_(n_joints)
    , generators_(n_joints)
  {}

  bool ChainTangent::factor(double shift)
  {
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero(); // S_j
    for (int j = 0; j < n_joints(); ++j)
      {
        const Eigen::Matrix3d &u = coupling_[j];
        const Eigen::LLT<Eigen::Matrix3d> pivot(diagonal_[j] + shift * Eigen::Matrix3d::Identity() -
                                                u * sum * u.transpose());
        if (pivot.info() != Eigen::Success)
          return false;
        // Explicit 3x3 inverse: all later work is fixed-size products.
        inverse_pivots_[j] = Eigen::Matrix3d(pivot.matrixL()).inverse();
        generators_[j]     = (axes_[j] - sum * u.transpose()) * inverse_pivots_[j].transpose();
        sum += generators_[j] * generators_[j].transpose();
      }
    return true;
  }

  void ChainTangent::solve(const Eigen::VectorXd &b, Eigen::VectorXd &x) const
  {
    Eigen::Vector3d carried = Eigen::Vector3d::Zero(); // s_j
    for (int j = 0; j < n_joints(); ++j)
      {
        const Eigen::Vector3d y = inverse_pivots_[j] * (b.segment<3>(3 * j) - coupling_[j] * carried);
        x.segment<3>(3 * j)     = y;
        carried += generators_[j] * y;
      }
    carried.setZero(); // t_j
    for (int j = n_joints() - 1; j >= 0; --j)
      {
        const Eigen::Vector3d y = x.segment<3>(3 * j) - generators_[j].transpose() * carried;
        x.segment<3>(3 * j)     = inverse_pivots_[j].transpose() * y;
        carried += coupling_[j].transpose() * x.segment<3>(3 * j);
      }
  }

  Eigen::MatrixXd ChainTangent::dense() const
  {
    Eigen::MatrixXd h(3 * n_joints(), 3 * n_joints());
    for (int j = 0; j < n_joints(); ++j)
      {
        h.block<3, 3>(3 * j, 3 * j) = diagonal_[j];
        for (int l = 0; l < j; ++l)
          {
            h.block<3, 3>(3 * j, 3 * l) = coupling_[j] * axes_[l];
            h.block<3, 3>(3 * l, 3 * j) = (coupling_[j] * axes_[l]).transpose();
          }
      }
    return h;
  }
} // namespace softchain::chain
