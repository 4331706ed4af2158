#include <softchain/chain/frictional_load_path.h>

#include <softchain/chain/aitken_relaxation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  // The solver's tolerance on the path: the looser of its own and the
  // steps' before the last step, its own on the last and after the path.
  FrictionalLoadPath::ToleranceOfSteps::ToleranceOfSteps(ChainEquilibrium &solver, const double steps)
    : solver_(solver)
    , final_(solver.tolerance())
    , steps_(std::max(steps, final_))
  {}

  FrictionalLoadPath::ToleranceOfSteps::~ToleranceOfSteps()
  {
    solver_.set_tolerance(final_);
  }

  void FrictionalLoadPath::ToleranceOfSteps::set(const bool last_step) const
  {
    solver_.set_tolerance(last_step ? final_ : steps_);
  }

  FrictionalLoadPath::FrictionalLoadPath(ChainEquilibrium &solver, const Settings settings)
    : solver_(solver)
    , settings_(settings)
  {
    if (settings_.steps < 1 || settings_.max_passes < 1 || !(settings_.tolerance > 0.0) ||
        !(settings_.step_tolerance > 0.0))
      throw std::invalid_argument("FrictionalLoadPath: steps, passes and tolerances must be positive");
  }

  bool FrictionalLoadPath::has_friction(const ChainLoad &load)
  {
    return std::any_of(load.obstacles.begin(), load.obstacles.end(),
                       [](const data::ObstacleRecord &o) { return o.friction > 0.0; });
  }

  ChainLoad FrictionalLoadPath::at(const ChainLoad &load, const double t) const
  {
    ChainLoad step = load;
    step.pressure  = t * load.pressure;
    for (PointLoad &p : step.point_loads)
      p.force *= t;
    step.path = t * load.path;
    return step;
  }

  // The largest change of a point's normal force (0 where it does not
  // touch) and of N |dn| against the largest normal force: a point that
  // grazes an obstacle may touch in one solve and not in the next, which
  // changes nothing once its force is below the tolerance.
  bool FrictionalLoadPath::settled(const std::vector<StickAnchor> &before,
                                   const std::vector<StickAnchor> &after) const
  {
    double largest = 0.0, change = 0.0;
    const auto compare = [&](const std::vector<StickAnchor> &these, const std::vector<StickAnchor> &those) {
      for (const StickAnchor &a : these)
        {
          const auto same = std::find_if(those.begin(), those.end(), [&](const StickAnchor &b) {
            return b.point == a.point && b.obstacle == a.obstacle;
          });
          largest = std::max(largest, a.normal_force);
          if (same == those.end())
            change = std::max(change, a.normal_force);
          else
            change = std::max({change, std::abs(a.normal_force - same->normal_force),
                               a.normal_force * (a.normal - same->normal).norm()});
        }
    };
    compare(after, before);
    compare(before, after);
    return change <= settings_.tolerance * largest;
  }

  Equilibrium FrictionalLoadPath::solve(const ChainLoad &load)
  {
    passes_ = 0;
    if (!has_friction(load))
      {
        passes_ = 1;
        return solver_.solve(load);
      }
    if (!load.anchors.empty())
      throw std::invalid_argument("FrictionalLoadPath: the path starts at rest, without anchors");
    std::vector<StickAnchor> anchors; // the last step's, slid
    Equilibrium              result;
    int                      iterations = 0;
    const ToleranceOfSteps   tolerance(solver_, settings_.step_tolerance);
    for (int step = 1; step <= settings_.steps; ++step)
      {
        tolerance.set(step == settings_.steps);
        result = solve_step(at(load, double(step) / settings_.steps), anchors, result.angles);
        iterations += result.iterations;
        if (!result.converged)
          {
            result.failure = "friction: load step " + std::to_string(step) + " of " +
                             std::to_string(settings_.steps) + ": " + result.failure;
            break;
          }
        anchors = solver_.contact().friction().slid_anchors();
      }
    result.iterations = iterations;
    return result;
  }

  // One step from the last one's angles `start` (none: from rest, the path's
  // first), solved again with the normal forces it finds, relaxed, until they
  // settle. Its iterations are all its solves'.
  Equilibrium FrictionalLoadPath::solve_step(ChainLoad load, const std::vector<StickAnchor> &anchors,
                                             const Eigen::VectorXd &start)
  {
    if (start.size() == 0) // the surface at rest
      {
        solver_.set_load(load);
        solver_.energy(Eigen::VectorXd::Zero(solver_.chain().n_angles()));
      }
    std::vector<Eigen::Vector3d> entered_from; // the surface's points at the step's start
    solver_.contact().surface_positions(solver_.pose(), entered_from);
    load.anchors = anchors;
    AitkenRelaxation relaxation;
    Eigen::VectorXd  q          = start;
    int              iterations = 0;
    for (int pass = 0; pass < settings_.max_passes; ++pass)
      {
        Equilibrium e = q.size() == 0 ? solver_.solve(load) : solver_.solve(load, q);
        ++passes_;
        iterations += e.iterations;
        e.iterations = iterations;
        if (!e.converged)
          return e;
        q = e.angles;
        const std::vector<StickAnchor> touching =
          solver_.contact().touching_anchors(solver_.pose(), load.anchors, entered_from);
        if (settled(load.anchors, touching))
          return e;
        load.anchors = relaxation.next(load.anchors, touching);
      }
    Equilibrium unsettled;
    unsettled.angles     = q;
    unsettled.iterations = iterations;
    unsettled.failure    = "the normal forces did not settle within " + std::to_string(settings_.max_passes) +
                        " solves";
    return unsettled;
  }
} // namespace softchain::chain
