#pragma once
// AffineSlabFit, method M2 of the paper (Sec. III-C, eq. 1): the affine map
// p_j = A_i p_j,0 + u_i that fits the slab's deformed nodes best in the least
// squares sense, and its polar decomposition A_i = R_i U_i (R_i a rotation,
// U_i = sqrt(A_i^T A_i) symmetric positive definite) computed through the
// SVD A = W S V^T: R = W V^T, U = V S V^T.
#include <softchain/reduction/slab_selection.h>

#include <Eigen/Core>

namespace softchain::reduction
{
  class AffineSlabFit
  {
  public:
    // Throws data::InputError naming joint and sample for a degenerate slab
    // (fewer than 4 nodes, or all nodes in one plane) or det A <= 0.
    AffineSlabFit(const SlabSelection &slab, const std::vector<data::Point3> &X,
                  const std::vector<data::Point3> &x, const std::string &sample);

    const Eigen::Matrix3d &rotation() const { return R_; }
    // Principal stretches of U_i (singular values of A_i), largest first.
    const Eigen::Vector3d &principal_stretches() const { return stretches_; }
    // Image of a reference point under the fitted map.
    Eigen::Vector3d map(const Eigen::Vector3d &X) const { return A_ * X + u_; }

  private:
    Eigen::Matrix3d A_;
    Eigen::Vector3d u_;
    Eigen::Matrix3d R_;
    Eigen::Vector3d stretches_;
  };
} // namespace softchain::reduction
