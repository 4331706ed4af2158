#pragma once
// NeoHookeanLog: W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, the
// compressible neo-Hookean model of VegaFEM used by the paper (Bonet & Wood,
// Nonlinear Continuum Mechanics for FEA, eq. 6.27).
//   tau = mu (b - I) + lambda ln J I
//   Jc  = lambda I(x)I + 2 (mu - lambda ln J) S      (S: symmetric identity)
#include <softchain/fem/hyperelastic_material.h>

namespace softchain::fem
{
  class NeoHookeanLog : public HyperelasticMaterial
  {
  public:
    NeoHookeanLog(double youngs_modulus, double poissons_ratio);
    double                strain_energy(const dealii::Tensor<2, 3> &F) const override;
    dealii::SymmetricTensor<2, 3> kirchhoff_stress(const dealii::Tensor<2, 3> &F) const override;
    IsotropicTangent spatial_tangent(const dealii::Tensor<2, 3> &F) const override;

  private:
    ElasticConstants constants;
  };
} // namespace softchain::fem
