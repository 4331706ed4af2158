// AffineSlabFit (M2). Least squares of eq. (1) of the paper,
//   min over A, u of sum_j |A p_j,0 + u - p_j|^2,
// gives, with centred coordinates P_j,0 = p_j,0 - mean(p_0) and
// P_j = p_j - mean(p), the normal equations A S0 = C,
//   S0 = sum_j P_j,0 P_j,0^T,  C = sum_j P_j P_j,0^T,  u = mean(p) - A mean(p_0).
// S0 is singular exactly when the slab's nodes lie in one plane.
#include <softchain/data/input_error.h>
#include <softchain/reduction/affine_slab_fit.h>
#include <softchain/data/vector_of_point.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace softchain::reduction
{
  namespace
  {
    [[noreturn]] void fail(const SlabSelection &slab, const std::string &sample,
                           const std::string &what)
    {
      throw data::InputError(slab.label() + ", sample '" + sample + "': " + what);
    }

    Eigen::Vector3d mean_of(const std::vector<std::size_t> &nodes,
                            const std::vector<data::Point3> &points)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const auto j : nodes)
        sum += data::vector_of(points[j]);
      return sum / static_cast<double>(nodes.size());
    }

    // Relative size of the smallest eigenvalue of S0 below which the slab is
    // taken as flat: the scatter sums carry a relative round-off of ~1e-16,
    // so 1e-12 leaves a margin of 1e4 and still accepts slabs 1e6 times
    // thinner than they are wide.
    constexpr double flat_slab_ratio = 1e-12;
  } // namespace

  AffineSlabFit::AffineSlabFit(const SlabSelection &slab, const std::vector<data::Point3> &X,
                               const std::vector<data::Point3> &x, const std::string &sample)
  {
    const auto &nodes = slab.nodes();
    if (nodes.size() < 4)
      fail(slab, sample, "degenerate slab of " + std::to_string(nodes.size()) +
                           " nodes; at least 4 nodes not in one plane are needed "
                           "(increase Reduction/Slab half-widths)");
    const Eigen::Vector3d mean_0 = mean_of(nodes, X);
    const Eigen::Vector3d mean   = mean_of(nodes, x);
    Eigen::Matrix3d       S0     = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d       C      = Eigen::Matrix3d::Zero();
    for (const auto j : nodes)
      {
        const Eigen::Vector3d P0 = data::vector_of(X[j]) - mean_0;
        S0 += P0 * P0.transpose();
        C += (data::vector_of(x[j]) - mean) * P0.transpose();
      }
    const Eigen::Vector3d eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(S0).eigenvalues();
    if (eigenvalues(0) <= flat_slab_ratio * eigenvalues(2))
      fail(slab, sample, "degenerate slab: its " + std::to_string(nodes.size()) +
                           " nodes lie in one plane");
    A_ = S0.ldlt().solve(C.transpose()).transpose();
    u_ = mean - A_ * mean_0;
    if (!(A_.determinant() > 0))
      fail(slab, sample, "the fitted affine map has det A = " + std::to_string(A_.determinant()) +
                           " <= 0 (reflected or collapsed slab)");
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(A_, Eigen::ComputeFullU | Eigen::ComputeFullV);
    R_         = svd.matrixU() * svd.matrixV().transpose();
    stretches_ = svd.singularValues();
  }
} // namespace softchain::reduction
