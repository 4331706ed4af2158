#include <softchain/fem/displacement_controlled_forces.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // f_1 - f_0 at every point of either state (a point of one state only
    // ramps from or to zero, as in LoadState::interpolate).
    std::vector<PointLoad> force_increment_of(const LoadState &start, const LoadState &target)
    {
      auto       increment = LoadState::interpolate(start, target, 1.0).point_loads;
      const auto from      = LoadState::interpolate(start, target, 0.0).point_loads;
      for (std::size_t k = 0; k < increment.size(); ++k)
        increment[k].force -= from[k].force;
      return increment;
    }

    double magnitude(const std::vector<PointLoad> &loads)
    {
      double sum = 0;
      for (const auto &l : loads)
        sum += l.force.norm_square();
      return std::sqrt(sum);
    }

    // The diagonal of the body's bounding box at rest, over all ranks.
    double body_diagonal(const FiniteElementSpace &space)
    {
      Point<3> low, high;
      for (unsigned int d = 0; d < 3; ++d)
        low[d] = std::numeric_limits<double>::max(), high[d] = -low[d];
      for (const auto &cell : space.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            for (unsigned int d = 0; d < 3; ++d)
              {
                low[d]  = std::min(low[d], cell->vertex(v)[d]);
                high[d] = std::max(high[d], cell->vertex(v)[d]);
              }
      double sum = 0;
      for (unsigned int d = 0; d < 3; ++d)
        sum += std::pow(Utilities::MPI::max(high[d], space.communicator) +
                          Utilities::MPI::max(-low[d], space.communicator),
                        2);
      return std::sqrt(sum);
    }

    std::vector<PointLoad> scaled(std::vector<PointLoad> loads, const double factor)
    {
      for (auto &l : loads)
        l.force *= factor;
      return loads;
    }
  } // namespace

  bool DisplacementControlledForces::applies(const LoadState &start, const LoadState &target)
  {
    const double scale = std::max(std::abs(target.pressure), 1.0);
    return !target.point_loads.empty() && !start.tip_motion && !target.tip_motion &&
           std::abs(start.pressure - target.pressure) <= 1e-9 * scale &&
           start.gravity_factor == target.gravity_factor &&
           start.tip_traction == target.tip_traction &&
           start.obstacle_motion == target.obstacle_motion &&
           magnitude(force_increment_of(start, target)) > 0;
  }

  DisplacementControlledForces::DisplacementControlledForces(QuasiStaticSolver &solver,
                                                             const Parameters  &prm,
                                                             const LoadState   &target)
    : BorderedLoadControl(solver, prm, 0.0)
    , start(solver.load_state())
    , target(target)
    , increment(force_increment_of(start, target))
    , force_increment(magnitude(increment))
    , q(solver.point_load_vector(scaled(increment, 1.0 / force_increment)))
  {}

  LoadState DisplacementControlledForces::load_at(const double mu) const
  {
    LoadState state = LoadState::interpolate(start, target, mu / force_increment);
    state.pressure  = target.pressure; // exactly, whatever the blend's round-off
    return state;
  }

  // The initial load step of the linear estimate of c's increment, F q.K^-1 q
  // at the start, as a fraction of the path's length `span` (the initial load
  // step itself where the estimate is not finite: a singular start).
  double DisplacementControlledForces::first_step(const double span)
  {
    const auto &s = solver.space();
    TrilinosWrappers::MPI::Vector b(s.owned_dofs, s.communicator);
    const double linear = solver.assemble(start, true) && solver.solve_tangent(q, b) ?
                            force_increment * std::abs(q * b) :
                            NAN;
    const double step   = prm.solver.initial_load_step;
    return std::isfinite(linear) && linear > 0 ?
             std::clamp(step * linear / span, prm.solver.min_load_step, step) :
             step;
  }

  DisplacementControlledForces::Result DisplacementControlledForces::solve()
  {
    Result       result;
    const double span  = body_diagonal(solver.space());
    const double first = first_step(span);
    const Path   path  = follow(conjugate_displacement() + span, first, "displacement factor");
    result.path              = path.points;
    result.newton_iterations = path.steps.newton_iterations;
    result.load_steps        = path.steps.load_steps;
    for (std::size_t k = 1; k < path.points.size() && !result.limit_fraction; ++k)
      if (path.points[k].load < path.points[k - 1].load)
        {
          result.limit_fraction = path.points[k - 1].load / force_increment;
          result.limit_force    = magnitude(load_at(path.points[k - 1].load).point_loads);
        }
    result.reached_fraction = load_amount() / force_increment;
    std::ostringstream why;
    if (!goal_reached())
      {
        why << "displacement control did not reach the forces: "
            << (path.steps.stop == LoadPath::Stop::too_many_attempts ?
                  "Solver/Maximum load step attempts used up" :
                path.steps.stop == LoadPath::Stop::step_too_small ?
                  "steps below Solver/Minimum load step failed (" + describe(path.steps.last_failure) + ")" :
                  "the force points moved the body's diagonal")
            << " at " << 100 * load_amount() / force_increment << " % of the force increment";
        result.reason = why.str();
        return result;
      }
    // Back to mu = F by load control, from the state that passed it.
    const auto last = solver.solve(target, 1.0);
    result.newton_iterations += last.newton_iterations;
    result.load_steps += last.load_steps;
    result.converged = last.converged;
    result.reached_fraction += (1.0 - result.reached_fraction) * last.load_factor_reached;
    if (!last.converged)
      result.reason = "displacement control passed the forces, but load control back to them failed: " +
                      last.reason;
    return result;
  }
} // namespace softchain::fem
