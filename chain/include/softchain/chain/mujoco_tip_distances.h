#pragma once
// mujoco_tip_distances: MuJoCo against the chain over the pressure. At each
// pressure (increasing: a staircase ramp, MujocoQuasiStatic) the finger at
// rest without forces in MuJoCo, once with the model set from the MJCF's
// pressure tables (MujocoPressureActuation) and once as plain MuJoCo with
// the exported constants K(p*), J_p(p*), against the chain's equilibrium
// (ChainEquilibrium) at that pressure: the distances between the tips.
#include <softchain/chain/chain_equilibrium.h>

#include <string>
#include <vector>

namespace softchain::chain
{
  struct MujocoTipDistance
  {
    double pressure;           // Pa
    double with_tables;        // m, MuJoCo set from the pressure tables
    double exported_constants; // m, plain MuJoCo
  };

  // `mjcf_path` is `chain` exported by MjcfExport; std::runtime_error if a
  // chain equilibrium fails, data::InputError if the MJCF is unusable.
  std::vector<MujocoTipDistance> mujoco_tip_distances(const ChainModel &chain, const std::string &mjcf_path,
                                                      const std::vector<double> &pressures,
                                                      const EquilibriumSettings &settings = {});
} // namespace softchain::chain
