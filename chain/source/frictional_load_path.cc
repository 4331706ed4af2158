#include <softchain/chain/frictional_load_path.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  FrictionalLoadPath::FrictionalLoadPath(ChainEquilibrium &solver, const Settings settings)
    : solver_(solver)
    , settings_(settings)
  {
    if (settings_.steps < 1 || settings_.max_passes < 1 || !(settings_.tolerance > 0.0))
      throw std::invalid_argument("FrictionalLoadPath: steps, passes and tolerance must be positive");
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

  bool FrictionalLoadPath::settled(const std::vector<StickAnchor> &before,
                                   const std::vector<StickAnchor> &after) const
  {
    if (before.size() != after.size())
      return false;
    double largest = 0.0, change = 0.0;
    for (const StickAnchor &a : after)
      {
        const auto same = std::find_if(before.begin(), before.end(), [&](const StickAnchor &b) {
          return b.point == a.point && b.obstacle == a.obstacle;
        });
        if (same == before.end())
          return false;
        largest = std::max(largest, a.normal_force);
        change  = std::max({change, std::abs(a.normal_force - same->normal_force),
                            a.normal_force * (a.normal - same->normal).norm()});
      }
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
    std::vector<StickAnchor>     anchors; // the last step's, slid
    std::vector<Eigen::Vector3d> start;   // the surface's points at the step's start
    Eigen::VectorXd              q;
    Equilibrium                  result;
    int                          iterations = 0;
    for (int step = 1; step <= settings_.steps; ++step)
      {
        const double t       = double(step) / settings_.steps;
        ChainLoad    at_step = at(load, t);
        if (step == 1)
          {
            solver_.set_load(at_step);
            solver_.energy(Eigen::VectorXd::Zero(solver_.chain().n_angles()));
          }
        solver_.contact().surface_positions(solver_.pose(), start);
        at_step.anchors = anchors;
        bool done       = false;
        for (int pass = 0; pass < settings_.max_passes && !done; ++pass)
          {
            result = step == 1 && pass == 0 ? solver_.solve(at_step) : solver_.solve(at_step, q);
            ++passes_;
            iterations += result.iterations;
            if (!result.converged)
              {
                result.failure = "friction: load step " + std::to_string(step) + " of " +
                                 std::to_string(settings_.steps) + ": " + result.failure;
                result.iterations = iterations;
                return result;
              }
            q = result.angles;
            std::vector<StickAnchor> touching =
              solver_.contact().touching_anchors(solver_.pose(), at_step.anchors, start);
            done            = settled(at_step.anchors, touching);
            at_step.anchors = std::move(touching);
          }
        if (!done)
          {
            result.converged = false;
            result.failure   = "friction: the normal forces did not settle within " +
                             std::to_string(settings_.max_passes) + " solves at load step " +
                             std::to_string(step) + " of " + std::to_string(settings_.steps);
            result.iterations = iterations;
            return result;
          }
        anchors = solver_.contact().friction().slid_anchors();
      }
    result.iterations = iterations;
    return result;
  }
} // namespace softchain::chain
