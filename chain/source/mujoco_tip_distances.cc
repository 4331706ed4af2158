#include <softchain/chain/mujoco_quasi_static.h>
#include <softchain/chain/mujoco_tip_distances.h>

#include <stdexcept>

namespace softchain::chain
{
  std::vector<MujocoTipDistance> mujoco_tip_distances(const ChainModel &chain, const std::string &mjcf_path,
                                                      const std::vector<double> &pressures,
                                                      const EquilibriumSettings &settings)
  {
    MujocoQuasiStatic with_tables(mjcf_path, MujocoQuasiStatic::Pressure::tables),
      plain(mjcf_path, MujocoQuasiStatic::Pressure::exported_constants);
    ChainEquilibrium               solver(chain, settings);
    std::vector<MujocoTipDistance> distances;
    for (const double p : pressures)
      {
        const Equilibrium e = solver.solve({p, {}});
        if (!e.converged)
          throw std::runtime_error("the chain has no equilibrium at " + std::to_string(p) + " Pa: " + e.failure);
        const Eigen::Vector3d tip = solver.pose().tip_position;
        distances.push_back({p, (with_tables.rest_pose(p).tip - tip).norm(), (plain.rest_pose(p).tip - tip).norm()});
      }
    return distances;
  }
} // namespace softchain::chain
