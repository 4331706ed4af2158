#pragma once
// HyperelasticMaterial: a compressible isotropic strain energy W(F), evaluated
// in the spatial form used by the assembly (deal.II step-44): the Kirchhoff
// stress tau = P F^T and the spatial tangent Jc (the push-forward of the
// material tangent, J times the Eulerian elasticity tensor), the latter by
// the coefficients of IsotropicTangent.
#include <softchain/fem/isotropic_tangent.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>

namespace softchain::fem
{
  // The compressible neo-Hookean energy of `Materials/Strain energy`.
  enum class StrainEnergy
  {
    log,  // NeoHookeanLog: mu/2 (I1-3) - mu ln J + lambda/2 (ln J)^2
    split // NeoHookeanSplit: mu/2 (I1bar-3) + kappa/4 (J^2-1-2 ln J)
  };

  class HyperelasticMaterial
  {
  public:
    virtual ~HyperelasticMaterial() = default;

    virtual double strain_energy(const dealii::Tensor<2, 3> &F) const = 0;
    // tau = 2 F dW/dC F^T
    virtual dealii::SymmetricTensor<2, 3> kirchhoff_stress(const dealii::Tensor<2, 3> &F) const = 0;
    // Jc_ijkl = 4 F_iI F_jJ F_kK F_lL d2W/dC_IJ dC_KL
    virtual IsotropicTangent spatial_tangent(const dealii::Tensor<2, 3> &F) const = 0;

    // NeoHookeanLog or NeoHookeanSplit with E [Pa] and nu.
    static std::unique_ptr<HyperelasticMaterial>
    create(StrainEnergy strain_energy, double youngs_modulus, double poissons_ratio);
  };

  // Lame parameters and bulk modulus from E and nu (linear elasticity).
  struct ElasticConstants
  {
    ElasticConstants(double youngs_modulus, double poissons_ratio);
    double mu;     // E / (2 (1 + nu))
    double lambda; // E nu / ((1 + nu)(1 - 2 nu))
    double kappa;  // E / (3 (1 - 2 nu))
  };
} // namespace softchain::fem
