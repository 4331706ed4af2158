#pragma once
// StiffnessPlots: PNG plots like the paper's Fig. 5-7, drawn by gnuplot from
// the CSV files of StiffnessTables: per method and b, k_phi along x for each
// pressure (Fig. 5a, 5b, 6); k_phi at the largest pressure for every method
// and b (Fig. 5c); k_psi (Fig. 5d) and k_theta (Fig. 7) along x. Curves and
// plots without any value (all "nan") are left out, since gnuplot stops on
// them. The gnuplot script stiffness/plots.gp is always written; it is run
// when `gnuplot` is on the PATH.
#include <string>
#include <vector>

namespace softchain::reduction
{
  class StiffnessPlots
  {
  public:
    // `labels`: the "<M>_b<f>a" of the tables already written in
    // `directory`; `spacing`: a.
    StiffnessPlots(std::string directory, std::vector<std::string> labels, double spacing);

    // Writes plots.gp and runs gnuplot on it if installed (its messages go
    // to plots.log). Returns whether gnuplot ran and succeeded.
    bool draw() const;

  private:
    std::string script() const;
    std::string per_pressure_plot(const std::string &label) const;
    std::string all_labels_plot(const std::string &name, const std::string &column) const;
    // Distinct pressures with a finite k_phi in <label>_kphi_vs_pressure.csv.
    std::vector<double> pressures_with_kphi(const std::string &label) const;
    // The labels whose <label>.csv has a finite value in `column`.
    std::vector<std::string> labels_with(const std::string &column) const;

    std::string              directory_;
    std::vector<std::string> labels_;
    double                   spacing_;
  };
} // namespace softchain::reduction
