#pragma once
// A design's output directory written by hand, as `softchain run` would:
// the database of a finger of two hexahedra with a converged 40 kPa sample
// and a failed 60 kPa one, the chain's stiffness table (M2, b = a/2), the
// validation summary and the .prm that selects that chain. No protocol:
// a test that needs one writes protocol_summary() below.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>

#include "../chain/box_mesh.h"
#include "../data/scratch_directory.h"

#include <fstream>
#include <string>
#include <vector>

namespace softchain::report::testing
{
  // <label>.csv of the reduction with the given per-joint values (joints
  // 1 cm apart); the columns the report and the claims do not read are 0.
  inline data::CsvTable stiffness_table(const std::vector<double> &k_psi, const std::vector<double> &k_phi,
                                        const std::vector<double> &joint_height)
  {
    data::CsvTable table({"joint", "x_ref", "Jx", "Jy", "Jz", "k_psi", "k_theta", "k_phi", "k_psi_fit",
                          "k_theta_fit", "k_phi_fit", "n_psi", "n_theta", "n_phi"});
    for (std::size_t j = 0; j < k_psi.size(); ++j)
      {
        const double x = 0.01 * (j + 0.5);
        table.add_row(std::vector<double>{double(j + 1), x, x, joint_height[j], 0, k_psi[j], 0.1, k_phi[j],
                                          k_psi[j], 0.1, k_phi[j], 2, 2, 2});
      }
    return table;
  }

  // validation_summary.csv with one chain row and one baseline row per role.
  inline data::CsvTable validation_summary(const double chain_mean_percent)
  {
    data::CsvTable table({"model", "roles", "n_samples", "n_failed", "max_tip_error_mm",
                          "mean_tip_error_mm", "max_tip_error_percent_L", "mean_tip_error_percent_L",
                          "max_orientation_error_deg", "mean_orientation_error_deg"});
    for (const std::string role : {"pressure", "validation"})
      {
        table.add_row({"M2", role, "2", "0", "1", "0.5", data::CsvTable::cell(2 * chain_mean_percent),
                       data::CsvTable::cell(chain_mean_percent), "2", "1"});
        table.add_row({"baseline", role, "2", "0", "8", "4", "80", "40", "50", "30"});
      }
    return table;
  }

  // protocol_summary.csv of the chain tier: three rows (Tx, Ty, Tz) for M2
  // and three for the baseline, whose Tz equilibria all failed (nan).
  // Torques in N m, errors in % of the FEM's range.
  inline data::CsvTable protocol_summary()
  {
    data::CsvTable table({"model", "torque", "fem_range_Nm", "rms_error_Nm", "rms_error_percent_range",
                          "max_error_percent_range", "n_failed_points"});
    table.add_row({"M2", "Tx", "0.0125", "0.0005", "4", "9.5", "0"});
    table.add_row({"M2", "Ty", "0.02", "0.00246912", "12.3456", "30.4", "0"});
    table.add_row({"M2", "Tz", "0.004", "0.0002", "5", "11", "1"});
    table.add_row({"baseline", "Tx", "0.0125", "0.0006", "4.8", "10", "0"});
    table.add_row({"baseline", "Ty", "0.02", "0.005", "25", "40", "0"});
    table.add_row({"baseline", "Tz", "0.004", "nan", "nan", "nan", "13"});
    return table;
  }

  class SyntheticOutputs
  {
  public:
    explicit SyntheticOutputs(const std::string &name)
      : root(name)
    {
      std::ofstream(prm()) << "subsection Chain\n  set Stiffness method = M2\n"
                              "  set Slab half-width = 0.5\nend\n";
      stiffness_table({0.3, 0.2, 0.1}, {NAN, 0.02, 0.01}, {0.01, 0.01, 0.01})
        .write(file("stiffness/M2_b0.50a.csv"));
      validation_summary(4).write(file("chain/validation_summary.csv"));
      write_database();
    }

    std::string prm() const { return root.file("design.prm"); }
    std::string directory() const { return root.file("finger"); }
    std::string database() const { return file("database.h5"); }
    std::string file(const std::string &relative) const { return directory() + "/" + relative; }
    // The output directory of another design beside this one.
    std::string sibling(const std::string &design) const { return root.file(design); }

  private:
    void write_database() const
    {
      chain::testing::BoxMeshSpec spec;
      spec.nx = 2, spec.ny = spec.nz = 1;
      const data::MeshRecord mesh = chain::testing::box_mesh(spec);
      auto stored = data::ActuationDatabase::open_or_create(
        database(), {"finger", "hash", "Q1", "test", "set Name = a<b"}, mesh);
      for (const double p : {40e3, 60e3})
        {
          data::SampleRecord s;
          s.actuation.pressure = p;
          s.actuation.role     = "pressure";
          s.id                 = data::sample_id("hash", s.actuation);
          s.status             = p < 50e3 ? data::SampleStatus::converged : data::SampleStatus::failed;
          s.reason             = p < 50e3 ? "" : "limit point at p = 55000 Pa";
          s.wall_time          = 1.25;
          for (const auto &X : mesh.X) // bent toward -y
            s.x.push_back({X[0], X[1] - X[0] * X[0], X[2]});
          stored.store_sample(s);
        }
    }

    softchain::testing::ScratchDirectory root;
  };
} // namespace softchain::report::testing
