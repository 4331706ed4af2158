#pragma once
// Central differences of the equilibrium's residual: the reference the
// exact tangent dr/dq is checked against. Each column errs by
// h^2/6 |r'''| + eps |r| / h.
#include <softchain/chain/chain_equilibrium.h>

namespace softchain::chain::testing
{
  inline Eigen::MatrixXd central_differences(ChainEquilibrium &solver, const Eigen::VectorXd &q,
                                             const double h)
  {
    Eigen::MatrixXd difference(q.size(), q.size());
    for (Eigen::Index j = 0; j < q.size(); ++j)
      {
        Eigen::VectorXd plus = q, minus = q;
        plus[j] += h;
        minus[j] -= h;
        difference.col(j) = (solver.residual(plus) - solver.residual(minus)) / (2 * h);
      }
    return difference;
  }

  // Central differences of the energy: the reference the residual (its
  // gradient) is checked against, one derivative lower.
  inline Eigen::VectorXd energy_gradient(ChainEquilibrium &solver, const Eigen::VectorXd &q, const double h)
  {
    Eigen::VectorXd gradient(q.size());
    for (Eigen::Index j = 0; j < q.size(); ++j)
      {
        Eigen::VectorXd plus = q, minus = q;
        plus[j] += h;
        minus[j] -= h;
        gradient[j] = (solver.energy(plus) - solver.energy(minus)) / (2 * h);
      }
    return gradient;
  }

  // The exact tangent's and residual's largest errors against central
  // differences with step h, relative to their largest entries.
  struct DerivativeErrors
  {
    double tangent;
    double gradient;
  };
  inline DerivativeErrors derivative_errors(ChainEquilibrium &solver, const Eigen::VectorXd &q, const double h)
  {
    const Eigen::MatrixXd tangent  = solver.tangent(q);
    const Eigen::VectorXd residual = solver.residual(q);
    return {(tangent - central_differences(solver, q, h)).cwiseAbs().maxCoeff() / tangent.cwiseAbs().maxCoeff(),
            (energy_gradient(solver, q, h) - residual).cwiseAbs().maxCoeff() / residual.cwiseAbs().maxCoeff()};
  }
} // namespace softchain::chain::testing
