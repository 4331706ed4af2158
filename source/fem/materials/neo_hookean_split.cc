#include <softchain/fem/neo_hookean_split.h>

#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  NeoHookeanSplit::NeoHookeanSplit(const double E, const double nu)
    : constants(E, nu)
  {}

  double NeoHookeanSplit::strain_energy(const Tensor<2, 3> &F) const
  {
    const double J       = determinant(F);
    const double I1_bar  = std::pow(J, -2.0 / 3.0) * trace(transpose(F) * F);
    return 0.5 * constants.mu * (I1_bar - 3.0) +
           0.25 * constants.kappa * (J * J - 1.0 - 2.0 * std::log(J));
  }

  SymmetricTensor<2, 3> NeoHookeanSplit::kirchhoff_stress(const Tensor<2, 3> &F) const
  {
    const double                J     = determinant(F);
    const SymmetricTensor<2, 3> b_bar = std::pow(J, -2.0 / 3.0) * symmetrize(F * transpose(F));
    return constants.mu * deviator(b_bar) +
           0.5 * constants.kappa * (J * J - 1.0) * unit_symmetric_tensor<3>();
  }

  // Jc_iso + Jc_vol with P = S - 1/3 I(x)I expanded (IsotropicTangent).
  IsotropicTangent NeoHookeanSplit::spatial_tangent(const Tensor<2, 3> &F) const
  {
    const double                J          = determinant(F);
    const SymmetricTensor<2, 3> b_bar      = std::pow(J, -2.0 / 3.0) * symmetrize(F * transpose(F));
    const double                tr_tau_bar = constants.mu * trace(b_bar);
    const double                kappa_J2   = constants.kappa * J * J;
    return {kappa_J2 - (2.0 / 9.0) * tr_tau_bar,
            (2.0 / 3.0) * tr_tau_bar - (kappa_J2 - constants.kappa),
            (-2.0 / 3.0) * constants.mu * deviator(b_bar)};
  }
} // namespace softchain::fem
