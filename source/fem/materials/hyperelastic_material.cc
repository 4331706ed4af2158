#include <softchain/fem/hyperelastic_material.h>
#include <softchain/fem/neo_hookean_log.h>
#include <softchain/fem/neo_hookean_split.h>

namespace softchain::fem
{
  using namespace dealii;

  ElasticConstants::ElasticConstants(const double E, const double nu)
    : mu(E / (2.0 * (1.0 + nu)))
    , lambda(E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)))
    , kappa(E / (3.0 * (1.0 - 2.0 * nu)))
  {}

  std::unique_ptr<HyperelasticMaterial>
  HyperelasticMaterial::create(const StrainEnergy strain_energy,
                               const double       youngs_modulus,
                               const double       poissons_ratio)
  {
    if (strain_energy == StrainEnergy::split)
      return std::make_unique<NeoHookeanSplit>(youngs_modulus, poissons_ratio);
    return std::make_unique<NeoHookeanLog>(youngs_modulus, poissons_ratio);
  }
} // namespace softchain::fem
