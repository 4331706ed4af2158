#include <softchain/data/content_hash.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  VolumeControlledInflation::VolumeControlledInflation(QuasiStaticSolver &solver,
                                                       const Parameters  &prm,
                                                       const double       start_pressure)
    : BorderedLoadControl(solver, prm, start_pressure)
  {}

  double VolumeControlledInflation::conjugate_displacement() const
  {
    return solver.pressure_load().cavity_volume(solver.displacement());
  }

  TrilinosWrappers::MPI::Vector VolumeControlledInflation::unit_load() const
  {
    TrilinosWrappers::MPI::Vector g(solver.negative_residual());
    g = 0;
    solver.pressure_load().assemble(solver.displacement(), 1.0, solver.space().fixed_dofs, nullptr, g);
    g.compress(VectorOperation::add);
    return g;
  }

  LoadState VolumeControlledInflation::load_at(const double p) const
  {
    LoadState state;
    state.pressure = p;
    return state;
  }

  VolumeControlledInflation::Result VolumeControlledInflation::solve(const double target_volume)
  {
    const Path path = follow(target_volume, prm.solver.initial_load_step, "volume factor");
    Result     result;
    for (const auto &point : path.points)
      result.curve.push_back({point.displacement, point.load});
    result.newton_iterations = path.steps.newton_iterations;
    result.converged         = path.steps.finished();
    if (!result.converged)
      {
        std::ostringstream why;
        why << "volume control did not converge "
            << (path.steps.stop == LoadPath::Stop::too_many_attempts ?
                  "in " + std::to_string(path.steps.attempts) +
                    " volume steps (Solver/Maximum load step attempts)" :
                  "even with volume steps below " + data::canonical(prm.solver.min_load_step))
            << " (last converged V = " << result.curve.back().volume
            << " m^3, p = " << pressure() << " Pa)";
        result.reason = why.str();
      }
    return result;
  }
} // namespace softchain::fem
