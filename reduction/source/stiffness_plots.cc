// StiffnessPlots: a gnuplot script over the stiffness CSV files.
#include <softchain/data/csv_table.h>
#include <softchain/reduction/stiffness_plots.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <fstream>
#include <sstream>

namespace softchain::reduction
{
  namespace
  {
    // The path in single quotes for the shell.
    std::string shell_quoted(const std::string &path)
    {
      std::string quoted = "'";
      for (const char c : path)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }

    bool gnuplot_installed()
    {
      return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
    }
  } // namespace

  StiffnessPlots::StiffnessPlots(std::string directory, std::vector<std::string> labels,
                                 double spacing)
    : directory_(std::move(directory))
    , labels_(std::move(labels))
    , spacing_(spacing)
  {}

  std::vector<double> StiffnessPlots::pressures_with_kphi(const std::string &label) const
  {
    const auto       table = data::CsvTable::read(directory_ + "/" + label + "_kphi_vs_pressure.csv");
    std::set<double> pressures;
    for (std::size_t r = 0; r < table.n_rows(); ++r)
      if (std::isfinite(table.number(r, "k_phi")))
        pressures.insert(table.number(r, "pressure"));
    return {pressures.begin(), pressures.end()};
  }

  std::vector<std::string> StiffnessPlots::labels_with(const std::string &column) const
  {
    std::vector<std::string> with;
    for (const auto &label : labels_)
      {
        const auto table = data::CsvTable::read(directory_ + "/" + label + ".csv");
        for (std::size_t r = 0; r < table.n_rows(); ++r)
          if (std::isfinite(table.number(r, column)))
            {
              with.push_back(label);
              break;
            }
      }
    return with;
  }

  // Fig. 5a/5b/6: k_phi along x, one curve per pressure; x = (joint - 1/2) a.
  std::string StiffnessPlots::per_pressure_plot(const std::string &label) const
  {
    std::ostringstream pressures, plot;
    pressures.precision(17);
    for (const double p : pressures_with_kphi(label))
      pressures << p << " ";
    if (pressures.str().empty())
      return "";
    plot << "set output \"" << directory_ << "/" << label << "_kphi_vs_x.png\"\n"
         << "set title \"k_phi along the finger, " << label << "\"\n"
         << "set ylabel \"k_phi (N m/rad)\"\n"
         << "plot for [P in \"" << pressures.str() << "\"] \"" << directory_ << "/" << label
         << "_kphi_vs_pressure.csv\" using ((column(\"pressure\") == P + 0) ? "
         << "(column(\"joint\") - 0.5) * " << spacing_ << " : NaN):\"k_phi\" "
         << "with linespoints title sprintf(\"p = %g kPa\", (P + 0) / 1000)\n";
    return plot.str();
  }

  // Fig. 5c (k_phi, every method and b), 5d (k_psi), 7 (k_theta).
  std::string StiffnessPlots::all_labels_plot(const std::string &name,
                                              const std::string &column) const
  {
    const std::vector<std::string> labels = labels_with(column);
    if (labels.empty())
      return "";
    std::ostringstream plot;
    plot << "set output \"" << directory_ << "/" << name << ".png\"\n"
         << "set title \"" << column << " at the largest load, every method and b\"\n"
         << "set ylabel \"" << column << " (N m/rad)\"\n"
         << "plot ";
    for (std::size_t i = 0; i < labels.size(); ++i)
      plot << (i ? ", " : "") << "\"" << directory_ << "/" << labels[i]
           << ".csv\" using \"x_ref\":\"" << column << "\" with linespoints title \"" << labels[i]
           << "\"";
    plot << "\n";
    return plot.str();
  }

  std::string StiffnessPlots::script() const
  {
    std::ostringstream script;
    script << "# SoftChain stiffness plots (reduction tier); run: gnuplot plots.gp\n"
           << "set terminal pngcairo noenhanced size 900,560\n"
           << "set datafile separator \",\"\n"
           << "set datafile columnheaders\n"
           << "set key outside right\n"
           << "set grid\n"
           << "set xlabel \"x (m)\"\n";
    for (const auto &label : labels_)
      script << per_pressure_plot(label);
    script << all_labels_plot("kphi_methods_and_b", "k_phi") << all_labels_plot("kpsi", "k_psi")
           << all_labels_plot("ktheta", "k_theta");
    return script.str();
  }

  bool StiffnessPlots::draw() const
  {
    const std::string path = directory_ + "/plots.gp";
    std::ofstream(path) << script();
    if (!gnuplot_installed())
      return false;
    const std::string command = "gnuplot " + shell_quoted(path) + " 2> " +
                                shell_quoted(directory_ + "/plots.log");
    return std::system(command.c_str()) == 0;
  }
} // namespace softchain::reduction
