#include <softchain/chain/validation_plot.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace softchain::chain
{
  ValidationPlot::ValidationPlot(std::string directory, std::vector<std::string> models)
    : directory_(std::move(directory))
    , models_(std::move(models))
  {}

  std::string ValidationPlot::script() const
  {
    const std::string  csv = "\"" + directory_ + "/validation.csv\"";
    std::ostringstream plots[2];
    const char        *columns[2] = {"tip_error_percent_L", "orientation_error_deg"};
    for (int panel = 0; panel < 2; ++panel)
      {
        plots[panel] << "plot ";
        for (std::size_t m = 0; m < models_.size(); ++m)
          plots[panel] << (m ? ", " : "") << csv << " using \"sample_index\":(strcol(\"model\") eq \""
                       << models_[m] << "\" ? column(\"" << columns[panel]
                       << "\") : NaN) with points pt " << 5 + 2 * m << " title \"" << models_[m]
                       << "\"";
        plots[panel] << "\n";
      }
    std::ostringstream s;
    s << "# Chain vs FEM tip pose per sample (softchain chain); run: gnuplot validation.gp\n"
      << "set terminal pngcairo size 900,800\n"
      << "set output \"" << directory_ << "/validation.png\"\n"
      << "set datafile separator \",\"\n"
      << "set datafile columnheaders\n"
      << "set grid\nset key outside right\nset xlabel \"sample\"\n"
      << "set xtics 1\nset offsets 0.5, 0.5, 0, 0\nset yrange [0:*]\n"
      << "set multiplot layout 2,1\n"
      << "set ylabel \"tip position error (% of L)\"\n"
      << plots[0].str() << "set ylabel \"tip orientation error (deg)\"\n"
      << plots[1].str() << "unset multiplot\n";
    return s.str();
  }

  bool run_gnuplot(const std::string &script_path, const std::string &script)
  {
    std::ofstream(script_path) << script;
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
      return false;
    return std::system(("gnuplot \"" + script_path + "\" > /dev/null 2>&1").c_str()) == 0;
  }

  bool ValidationPlot::draw() const
  {
    return run_gnuplot(directory_ + "/validation.gp", script());
  }
} // namespace softchain::chain
