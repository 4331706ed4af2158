#include <softchain/app/solve_loads.h>

namespace softchain::app
{
  using namespace dealii;
  using namespace softchain::fem;

  QuasiStaticSolver::Result solve_loads(QuasiStaticSolver &solver, const Parameters &prm,
                                        std::ostream &out)
  {
    LoadState target;
    target.obstacle_motion = 1.0;
    target.pressure       = prm.loads.pressure;
    target.point_loads    = prm.loads.point_loads;
    target.gravity_factor = prm.loads.gravity ? 1.0 : 0.0;
    target.tip_traction   = prm.loads.tip_traction;
    auto result           = solver.solve(target);
    if (prm.loads.prescribe_tip && result.converged) // then the tip moves from that state
      {
        target.tip_motion = TipMotion{prm.loads.tip_translation, prm.loads.tip_rotation,
                                      prm.loads.tip_point_contact};
        const auto moved  = solver.solve(target);
        out << "loads: " << result.load_steps << " load steps; tip motion: " << moved.load_steps
            << " load steps\n";
        result.converged = moved.converged;
        result.reason    = moved.reason;
        result.load_factor_reached = moved.load_factor_reached;
        result.newton_iterations += moved.newton_iterations;
        result.load_steps += moved.load_steps;
        result.wall_time += moved.wall_time;
      }
    return result;
  }
} // namespace softchain::app
