// Both strain energies against central differences of their own energy, at
// large random deformations: the Kirchhoff stress against dW, and the
// spatial tangent (IsotropicTangent, three coefficients) against the
// derivative of the second Piola-Kirchhoff stress, pushed forward.
// A symmetric material direction M is reached by dF = (h/2) F^-T M, for
// which dC = dF^T F + F^T dF = h M exactly; with S = F^-1 tau F^-T,
//     dW/dh      = S : M / 2,
//     Jc : m     = F (dS/dh) F^T  (times 2, C_mat = 2 dS/dC) for M = F^T m F.
#include <softchain/fem/hyperelastic_material.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace dealii;
using namespace softchain::fem;

namespace
{
  // F = I + a random matrix of entries in [-0.3, 0.3]: stretches to about
  // 1.5 and shears of 0.3, J between about 0.5 and 1.8 (det F > 0 checked).
  Tensor<2, 3> random_deformation(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> entry(-0.3, 0.3);
    Tensor<2, 3>                           F = unit_symmetric_tensor<3>();
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        F[i][j] += entry(random);
    return F;
  }

  SymmetricTensor<2, 3> random_symmetric(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> entry(-1, 1);
    SymmetricTensor<2, 3>                  m;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        m[i][j] = entry(random);
    return m;
  }

  // F moved so that C moves by s M.
  Tensor<2, 3> moved(const Tensor<2, 3> &F, const SymmetricTensor<2, 3> &M, const double s)
  {
    return F + (s / 2) * transpose(invert(F)) * Tensor<2, 3>(M);
  }

  SymmetricTensor<2, 3> second_piola(const HyperelasticMaterial &material, const Tensor<2, 3> &F)
  {
    const Tensor<2, 3> F_inv = invert(F);
    return symmetrize(F_inv * Tensor<2, 3>(material.kirchhoff_stress(F)) * transpose(F_inv));
  }
} // namespace

TEST_CASE("Kirchhoff stress and spatial tangent match central differences of the energy",
          "[fem][tangent]")
{
  // E and nu of the paper's silicone.
  const StrainEnergy energy = GENERATE(StrainEnergy::log, StrainEnergy::split);
  const auto         material = HyperelasticMaterial::create(energy, 2.6e5, 0.48);
  std::mt19937       random(7);
  // h = 1e-5: the central differences' truncation error is O(h^2) = 1e-10
  // relative; their round-off, 1e-16 |W| / h, is 1e-11 relative. Measured
  // relative errors over these samples: up to 1.6e-9 (stress) and 8.3e-10
  // (tangent); the tolerance is 1e-8 for both. A wrong coefficient gives
  // errors far above it (gamma off by 1 % alone: 3e-3).
  const double h = 1e-5;
  for (int sample = 0; sample < 20; ++sample)
    {
      const Tensor<2, 3> F = random_deformation(random);
      REQUIRE(determinant(F) > 0.1);
      const SymmetricTensor<2, 3> M = random_symmetric(random);
      INFO("energy " << static_cast<int>(energy) << ", sample " << sample << ", J "
                     << determinant(F));

      const double dW = (material->strain_energy(moved(F, M, h)) -
                         material->strain_energy(moved(F, M, -h))) / (2 * h);
      const double S_M = second_piola(*material, F) * M / 2;
      CHECK(std::abs(dW - S_M) <= 1e-8 * second_piola(*material, F).norm() * M.norm());

      const SymmetricTensor<2, 3> dS =
        (second_piola(*material, moved(F, M, h)) - second_piola(*material, moved(F, M, -h))) / (2 * h);
      const SymmetricTensor<2, 3> finite_difference = 2 * symmetrize(F * Tensor<2, 3>(dS) * transpose(F));
      // m = F^-T M F^-1, so that F^T m F = M.
      const Tensor<2, 3>          F_inv = invert(F);
      const SymmetricTensor<2, 3> m     = symmetrize(transpose(F_inv) * Tensor<2, 3>(M) * F_inv);
      const SymmetricTensor<2, 3> Jc_m  = material->spatial_tangent(F).apply(m);
      CHECK((Jc_m - finite_difference).norm() <= 1e-8 * finite_difference.norm());
    }
}
