#include <softchain/fem/sweep_progress.h>

#include <iomanip>

namespace softchain::fem
{
  SweepProgress::SweepProgress(std::ostream &out, const std::size_t n_samples,
                               const std::size_t n_to_solve, const unsigned int n_groups)
    : out(out)
    , n_samples(n_samples)
    , n_to_solve(n_to_solve)
    , n_groups(n_groups)
  {}

  std::ostream &SweepProgress::start_line(const Sample &sample)
  {
    const int width = std::to_string(n_samples).size();
    return out << '[' << std::setw(width) << ++n_done << '/' << n_samples << "] " << std::left
               << std::setw(22) << sample.label << std::right;
  }

  void SweepProgress::cached(const Sample &sample, const data::SampleRecord &record)
  {
    start_line(sample) << " cached (" << data::status_name(record.status) << ")" << std::endl;
  }

  void SweepProgress::solved(const Sample &sample, const data::SampleRecord &record,
                             const data::MeshRecord &mesh)
  {
    ++n_solved;
    solve_time += record.wall_time;
    const double eta = solve_time / n_solved * (n_to_solve - n_solved) / n_groups;
    start_line(sample) << ' ' << std::setw(9) << data::status_name(record.status) << std::setw(4)
                       << record.load_steps << " load steps" << std::setw(4)
                       << record.newton_iterations << " Newton it. " << std::fixed
                       << std::setprecision(2) << std::setw(7) << record.wall_time << " s  ETA "
                       << eta << " s";
    if (record.x.size() == mesh.X.size() && !mesh.tip_nodes.empty())
      {
        double u[3] = {0, 0, 0};
        for (const auto node : mesh.tip_nodes)
          for (unsigned int d = 0; d < 3; ++d)
            u[d] += (record.x[node][d] - mesh.X[node][d]) / mesh.tip_nodes.size();
        out << "  tip u = (" << std::setprecision(2) << 1e3 * u[0] << ", " << 1e3 * u[1] << ", "
            << 1e3 * u[2] << ") mm";
      }
    if (record.actuation.cavity_volume_ratio) // the pressure volume control found
      out << "  p = " << std::setprecision(0) << record.actuation.pressure << " Pa";
    if (record.converged() && !record.reason.empty()) // how it was reached
      out << "  (" << record.reason << ')';
    out << std::defaultfloat << std::endl;
  }
} // namespace softchain::fem
