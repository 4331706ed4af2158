#include <softchain/chain/protocol_plot.h>
#include <softchain/chain/validation_plot.h>

#include <sstream>

namespace softchain::chain
{
  std::string protocol_plot_script(const std::string &directory, const std::vector<std::string> &models)
  {
    const std::string  csv = "\"" + directory + "/protocol_torques.csv\"";
    std::ostringstream s;
    s << "# Base torques over the tip-motion protocol (softchain chain); run: gnuplot "
         "protocol_torques.gp\n"
      << "set terminal pngcairo size 900,1000\n"
      << "set output \"" << directory << "/protocol_torques.png\"\n"
      << "set datafile separator \",\"\n"
      << "set datafile columnheaders\n"
      << "set grid\nset key outside right\nset xlabel \"trace step (lateral, bending, twist)\"\n"
      << "set multiplot layout 3,1\n";
    for (const char *torque : {"Tx", "Ty", "Tz"})
      {
        s << "set ylabel \"" << torque << " (mN m)\"\n"
          << "plot " << csv << " using \"step\":(1e3*column(\"fem_" << torque
          << "\")) with linespoints lc black lw 2 pt 7 ps 0.5 title \"FEM\"";
        for (std::size_t m = 0; m < models.size(); ++m)
          s << ", " << csv << " using \"step\":(1e3*column(\"" << models[m] << "_" << torque
            << "\")) with lines lw 2 " << (models[m] == "baseline" ? "dt 2 lc rgb \"gray40\"" : "")
            << " title \"" << models[m] << "\"";
        s << "\n";
      }
    s << "unset multiplot\n";
    return s.str();
  }

  bool draw_protocol_plot(const std::string &directory, const std::vector<std::string> &models)
  {
    return run_gnuplot(directory + "/protocol_torques.gp", protocol_plot_script(directory, models));
  }
} // namespace softchain::chain
