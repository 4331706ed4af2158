#pragma once
// NeoHookeanLog: W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, the
// compressible neo-Hookean model of VegaFEM used by the paper (Bonet & Wood,
// Nonlinear Continuum Mechanics for FEA, eq. 6.27).
//   tau = mu (b - I) + lambda ln J I
//   Jc  = lambda I(x)I + 2 (mu - lambda ln J) S      (S: symmetric identity)
#include <softchain/hyperelastic_material.h>

namespace softchain
{
  class NeoHookeanLog : public HyperelasticMaterial
  {
  public:
    NeoHookeanLog(double youngs_modulus, double poissons_ratio);
    double                strain_energy(const Tensor<2, 3> &F) const override;
    SymmetricTensor<2, 3> kirchhoff_stress(const Tensor<2, 3> &F) const override;
    SymmetricTensor<4, 3> spatial_tangent(const Tensor<2, 3> &F) const override;

  private:
    ElasticConstants constants;
  };
} // namespace softchain
