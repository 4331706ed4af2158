#pragma once
// NeoHookeanSplit: W = mu/2 (I1bar - 3) + kappa/4 (J^2 - 1 - 2 ln J), the
// isochoric/volumetric split (Holzapfel, Nonlinear Solid Mechanics, Sec. 6.4;
// the deal.II code-gallery Cook's membrane example; CalculiX's form with
// C10 = mu/2, D1 = 2/kappa up to its volumetric function).
//   tau_iso = mu dev(bbar),  tau_vol = kappa/2 (J^2 - 1) I
//   Jc_iso  = 2/3 tr(mu bbar) P - 2/3 (tau_iso (x) I + I (x) tau_iso)
//   Jc_vol  = kappa J^2 I(x)I - kappa (J^2 - 1) S
// with P = S - 1/3 I(x)I the deviatoric projector.
#include <softchain/fem/hyperelastic_material.h>

namespace softchain::fem
{
  class NeoHookeanSplit : public HyperelasticMaterial
  {
  public:
    NeoHookeanSplit(double youngs_modulus, double poissons_ratio);
    double                strain_energy(const dealii::Tensor<2, 3> &F) const override;
    dealii::SymmetricTensor<2, 3> kirchhoff_stress(const dealii::Tensor<2, 3> &F) const override;
    IsotropicTangent spatial_tangent(const dealii::Tensor<2, 3> &F) const override;

  private:
    ElasticConstants constants;
  };
} // namespace softchain::fem
