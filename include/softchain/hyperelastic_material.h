#pragma once
// HyperelasticMaterial: a compressible isotropic strain energy W(F), evaluated
// in the spatial form used by the assembly (deal.II step-44): the Kirchhoff
// stress tau = P F^T and the spatial tangent Jc (the push-forward of the
// material tangent, J times the Eulerian elasticity tensor).
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace softchain
{
  using namespace dealii;

  class HyperelasticMaterial
  {
  public:
    virtual ~HyperelasticMaterial() = default;

    virtual double strain_energy(const Tensor<2, 3> &F) const = 0;
    // tau = 2 F dW/dC F^T
    virtual SymmetricTensor<2, 3> kirchhoff_stress(const Tensor<2, 3> &F) const = 0;
    // Jc_ijkl = 4 F_iI F_jJ F_kK F_lL d2W/dC_IJ dC_KL
    virtual SymmetricTensor<4, 3> spatial_tangent(const Tensor<2, 3> &F) const = 0;

    // "log" or "split" (see NeoHookeanLog, NeoHookeanSplit); E [Pa], nu.
    static std::unique_ptr<HyperelasticMaterial>
    create(const std::string &strain_energy, double youngs_modulus, double poissons_ratio);
  };

  // Lame parameters and bulk modulus from E and nu (linear elasticity).
  struct ElasticConstants
  {
    ElasticConstants(double youngs_modulus, double poissons_ratio);
    double mu;     // E / (2 (1 + nu))
    double lambda; // E nu / ((1 + nu)(1 - 2 nu))
    double kappa;  // E / (3 (1 - 2 nu))
  };
} // namespace softchain
