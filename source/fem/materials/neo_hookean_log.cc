#include <softchain/fem/neo_hookean_log.h>

#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  NeoHookeanLog::NeoHookeanLog(const double E, const double nu)
    : constants(E, nu)
  {}

  double NeoHookeanLog::strain_energy(const Tensor<2, 3> &F) const
  {
    const double lnJ = std::log(determinant(F));
    const double I1  = trace(transpose(F) * F);
    return 0.5 * constants.mu * (I1 - 3.0) - constants.mu * lnJ +
           0.5 * constants.lambda * lnJ * lnJ;
  }

  SymmetricTensor<2, 3> NeoHookeanLog::kirchhoff_stress(const Tensor<2, 3> &F) const
  {
    const SymmetricTensor<2, 3> b   = symmetrize(F * transpose(F));
    const SymmetricTensor<2, 3> I   = unit_symmetric_tensor<3>();
    const double                lnJ = std::log(determinant(F));
    return constants.mu * (b - I) + constants.lambda * lnJ * I;
  }

  // Jc = lambda I(x)I + 2 (mu - lambda ln J) S.
  IsotropicTangent NeoHookeanLog::spatial_tangent(const Tensor<2, 3> &F) const
  {
    const double lnJ = std::log(determinant(F));
    return {constants.lambda, 2.0 * (constants.mu - constants.lambda * lnJ), {}};
  }
} // namespace softchain::fem
