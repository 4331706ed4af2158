#pragma once
// Writes the reduction tier's stiffness CSVs for a uniform straight finger
// (joints at (i + 1/2) a on the x axis), the input of the chain tests.
#include <softchain/chain/stiffness_files.h>
#include <softchain/data/csv_table.h>

#include <cmath>
#include <string>
#include <vector>

namespace softchain::chain::testing
{
  struct UniformReduction
  {
    int             n = 9;
    double          a = 0.01;
    Eigen::Vector3d k{0.2, 0.05, 0.05};     // value columns
    Eigen::Vector3d k_fit{0.19, 0.06, 0.04}; // fit columns
    Eigen::Vector3d jp{0.0, 0.0, 2e-7};     // rest J_p, N m / Pa
    double          jp_growth  = 0.5;       // J_p(p_max) = (1 + growth) J_p(0)
    double          p_max      = 8e4;       // Pa
    double          k_phi_drop = 0.3;       // k_phi(p_max) = (1 - drop) k_phi
    double          twist_height = 0.0;     // S_i = J_i + (0, twist_height, 0)
  };

  inline data::CsvTable stiffness_table(const UniformReduction &r)
  {
    // The twist axis columns only where the twist axis is not the joint's
    // (the reduction's files before them had none).
    const bool twist = r.twist_height != 0.0;
    std::vector<std::string> columns = {"joint", "x_ref", "Jx", "Jy", "Jz"};
    if (twist)
      columns.insert(columns.end(), {"Sx", "Sy", "Sz"});
    columns.insert(columns.end(), {"k_psi", "k_theta", "k_phi", "k_psi_fit", "k_theta_fit",
                                   "k_phi_fit", "n_psi", "n_theta", "n_phi"});
    data::CsvTable table(columns);
    for (int i = 0; i < r.n; ++i)
      {
        const double        x   = (i + 0.5) * r.a;
        std::vector<double> row = {double(i + 1), x, x, 0.0, 0.0};
        if (twist)
          row.insert(row.end(), {x, r.twist_height, 0.0});
        row.insert(row.end(), {r.k[0], r.k[1], r.k[2], r.k_fit[0], r.k_fit[1], r.k_fit[2], 3, 3, 8});
        table.add_row(row);
      }
    return table;
  }

  // Writes the three files of `files` (NaN k_phi at p = 0: no rotation there).
  inline void write_reduction(const StiffnessFiles &files, const UniformReduction &r)
  {
    stiffness_table(r).write(files.stiffness_path());
    data::CsvTable bending({"pressure", "joint", "k_phi"});
    data::CsvTable torque({"pressure", "joint", "jp_x", "jp_y", "jp_z"});
    for (const double p : {0.0, 0.5 * r.p_max, r.p_max})
      for (int i = 0; i < r.n; ++i)
        {
          const double          s = p / r.p_max;
          const Eigen::Vector3d jp = (1.0 + r.jp_growth * s) * r.jp;
          bending.add_row(std::vector<double>{p, double(i + 1),
                                              p == 0.0 ? NAN : (1.0 - r.k_phi_drop * s) * r.k[2]});
          torque.add_row(std::vector<double>{p, double(i + 1), jp[0], jp[1], jp[2]});
        }
    bending.write(files.bending_in_pressure_path());
    torque.write(files.pressure_torque_path());
  }
} // namespace softchain::chain::testing
