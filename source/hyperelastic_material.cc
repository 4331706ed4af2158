#include <softchain/data/input_error.h>
#include <softchain/hyperelastic_material.h>
#include <softchain/neo_hookean_log.h>
#include <softchain/neo_hookean_split.h>

namespace softchain
{
  ElasticConstants::ElasticConstants(const double E, const double nu)
    : mu(E / (2.0 * (1.0 + nu)))
    , lambda(E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)))
    , kappa(E / (3.0 * (1.0 - 2.0 * nu)))
  {}

  std::unique_ptr<HyperelasticMaterial>
  HyperelasticMaterial::create(const std::string &strain_energy,
                               const double       youngs_modulus,
                               const double       poissons_ratio)
  {
    if (strain_energy == "log")
      return std::make_unique<NeoHookeanLog>(youngs_modulus, poissons_ratio);
    if (strain_energy == "split")
      return std::make_unique<NeoHookeanSplit>(youngs_modulus, poissons_ratio);
    throw data::InputError("unknown strain energy '" + strain_energy +
                           "' (Materials/Strain energy: log or split)");
  }
} // namespace softchain
