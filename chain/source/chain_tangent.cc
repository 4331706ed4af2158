#include <softchain/chain/chain_tangent.h>

#include <cmath>

namespace softchain::chain
{
  namespace
  {
    // L^-1 for the Cholesky factor L L^T = a of a symmetric 3x3 matrix (lower
    // triangle read), written out; false if a is not positive definite.
    bool inverse_cholesky_factor(const Eigen::Matrix3d &a, Eigen::Matrix3d &inverse)
    {
      const double l00 = std::sqrt(a(0, 0));
      const double l10 = a(1, 0) / l00, l20 = a(2, 0) / l00;
      const double l11 = std::sqrt(a(1, 1) - l10 * l10);
      const double l21 = (a(2, 1) - l20 * l10) / l11;
      const double l22 = std::sqrt(a(2, 2) - l20 * l20 - l21 * l21);
      if (!(l00 > 0.0 && l11 > 0.0 && l22 > 0.0)) // also catches NaN (negative radicands)
        return false;
      const double m00 = 1.0 / l00, m11 = 1.0 / l11, m22 = 1.0 / l22;
      const double m10 = -l10 * m00 * m11;
      inverse << m00, 0.0, 0.0, //
        m10, m11, 0.0,          //
        -(l20 * m00 + l21 * m10) * m22, -l21 * m11 * m22, m22;
      return true;
    }
  } // namespace

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
        const Eigen::Matrix3d &u      = coupling_[j];
        const Eigen::Matrix3d  s_ut   = sum * u.transpose(); // S_j U_j^T, used twice
        if (!inverse_cholesky_factor(diagonal_[j] + shift * Eigen::Matrix3d::Identity() - u * s_ut,
                                     inverse_pivots_[j]))
          return false;
        generators_[j].noalias() = (axes_[j] - s_ut) * inverse_pivots_[j].transpose();
        sum.noalias() += generators_[j] * generators_[j].transpose();
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
        carried.noalias() += generators_[j] * y;
      }
    carried.setZero(); // t_j
    for (int j = n_joints() - 1; j >= 0; --j)
      {
        const Eigen::Vector3d y  = x.segment<3>(3 * j) - generators_[j].transpose() * carried;
        const Eigen::Vector3d xj = inverse_pivots_[j].transpose() * y;
        x.segment<3>(3 * j)      = xj;
        carried.noalias() += coupling_[j].transpose() * xj;
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
