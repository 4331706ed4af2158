// StiffnessPlots: a gnuplot script over the stiffness CSV files.
#include <softchain/reduction/stiffness_plots.h>

#include <cstdlib>
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
                                 std::vector<double> pressures, double spacing)
    : directory_(std::move(directory))
    , labels_(std::move(labels))
    , pressures_(std::move(pressures))
    , spacing_(spacing)
  {}

  // Fig. 5a/5b/6: k_phi along x, one curve per pressure; x = (joint - 1/2) a.
  std::string StiffnessPlots::per_pressure_plot(const std::string &label) const
  {
    std::ostringstream pressures, plot;
    pressures.precision(17);
    for (const double p : pressures_)
      pressures << p << " ";
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
  std::string StiffnessPlots::all_labels_plot(const std::string &name, const std::string &column,
                                              const std::string &ylabel) const
  {
    std::ostringstream plot;
    plot << "set output \"" << directory_ << "/" << name << ".png\"\n"
         << "set title \"" << column << " at the largest load, every method and b\"\n"
         << "set ylabel \"" << ylabel << "\"\n"
         << "plot ";
    for (std::size_t i = 0; i < labels_.size(); ++i)
      plot << (i ? ", " : "") << "\"" << directory_ << "/" << labels_[i]
           << ".csv\" using \"x_ref\":\"" << column << "\" with linespoints title \"" << labels_[i]
           << "\"";
    plot << "\n";
    return plot.str();
  }

  std::string StiffnessPlots::script() const
  {
    std::ostringstream script;
    script << "# SoftChain stiffness plots (reduction tier); run: gnuplot plots.gp\n"
           << "set terminal pngcairo size 900,560\n"
           << "set datafile separator \",\"\n"
           << "set datafile columnheaders\n"
           << "set key outside right\n"
           << "set grid\n"
           << "set xlabel \"x (m)\"\n";
    if (!pressures_.empty())
      for (const auto &label : labels_)
        script << per_pressure_plot(label);
    script << all_labels_plot("kphi_methods_and_b", "k_phi", "k_phi (N m/rad)")
           << all_labels_plot("kpsi", "k_psi", "k_psi (N m/rad)")
           << all_labels_plot("ktheta", "k_theta", "k_theta (N m/rad)");
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
