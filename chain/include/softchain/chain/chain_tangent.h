#pragma once
// ChainTangent: the Newton matrix H = K - dQ/dq of a serial chain in the
// structured form that ChainEquilibrium derives (see there):
//   H_jj = D_j (symmetric 3x3),   H_jl = U_j A_l  for l < j,   H_lj = H_jl^T,
// with A_l the joint axes of joint l and U_j = -A_j^T (B_j + [M_j]x) a factor
// of joint j alone: a block semiseparable matrix. Its Cholesky factor keeps
// the form, L_jl = U_j Z_l (l < j), which gives the O(n) recursion
//   S_0 = 0,   L_jj L_jj^T = D_j + shift I - U_j S_j U_j^T,
//   Z_j = (A_j - S_j U_j^T) L_jj^-T,   S_{j+1} = S_j + Z_j Z_j^T
// (equate H_jl = sum_{m<=l} L_jm L_lm^T block by block), and the solves
//   forward  y_j = L_jj^-1 (b_j - U_j s_j),           s_{j+1} = s_j + Z_j y_j
//   backward x_j = L_jj^-T (y_j - Z_j^T t_j),         t_{j-1} = t_j + U_j^T x_j.
// So a Newton step costs O(n) 3x3 operations instead of a dense O(n^3)
// factorization; H is positive definite exactly when every L_jj exists.
#include <Eigen/Core>
#include <vector>

namespace softchain::chain
{
  class ChainTangent
  {
  public:
    explicit ChainTangent(int n_joints);

    int n_joints() const { return static_cast<int>(diagonal_.size()); }
    Eigen::Matrix3d &diagonal(int j) { return diagonal_[j]; } // D_j
    Eigen::Matrix3d &coupling(int j) { return coupling_[j]; } // U_j
    Eigen::Matrix3d &axes(int j) { return axes_[j]; }         // A_j

    // Factorizes H + shift I; false if it is not positive definite.
    bool factor(double shift);
    // x = (H + shift I)^-1 b with the last factorization.
    void solve(const Eigen::VectorXd &b, Eigen::VectorXd &x) const;
    // H as a dense matrix (for inspection and tests).
    Eigen::MatrixXd dense() const;

  private:
    std::vector<Eigen::Matrix3d>              diagonal_, coupling_, axes_;
    std::vector<Eigen::Matrix3d>              inverse_pivots_; // L_jj^-1
    std::vector<Eigen::Matrix3d>              generators_; // Z_j
  };
} // namespace softchain::chain
