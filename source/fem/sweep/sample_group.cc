#include <softchain/fem/displacement_controlled_forces.h>
#include <softchain/fem/sample_group.h>
#include <softchain/fem/solution_output.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    std::vector<Point<3>> points_of(const data::Actuation &actuation)
    {
      std::vector<Point<3>> points;
      for (const auto &f : actuation.point_forces)
        points.emplace_back(f.point[0], f.point[1], f.point[2]);
      return points;
    }

    LoadState load_of(const data::Actuation &actuation)
    {
      LoadState load;
      load.pressure = actuation.pressure;
      for (const auto &f : actuation.point_forces)
        load.point_loads.push_back({Point<3>(f.point[0], f.point[1], f.point[2]),
                                    Point<3>(f.force[0], f.force[1], f.force[2])});
      load.obstacle_motion = actuation.obstacles.empty() ? 0.0 : 1.0; // the obstacles at their final place
      if (const auto &m = actuation.tip_motion)
        load.tip_motion = TipMotion{Tensor<1, 3>({m->translation[0], m->translation[1], m->translation[2]}),
                                    Tensor<1, 3>({m->rotation[0], m->rotation[1], m->rotation[2]}),
                                    m->point_contact};
      return load;
    }

    data::Point3 triple(const Tensor<1, 3> &v) { return {{v[0], v[1], v[2]}}; }

    // The sweep's solver starts without obstacles; each contact sample
    // brings its own (SampleGroup::solve).
    Parameters without_obstacles(Parameters prm)
    {
      prm.contact = prm.contact.with({});
      return prm;
    }

    // |t| + |theta| of a tip motion [mixed units: one of them grows along a
    // protocol chain]; 0 without one.
    double motion_size(const std::optional<data::TipMotion> &m)
    {
      return m ? std::hypot(m->translation[0], m->translation[1], m->translation[2]) +
                   std::hypot(m->rotation[0], m->rotation[1], m->rotation[2]) :
                 0.0;
    }
  } // namespace

  SampleGroup::SampleGroup(const Parameters &parameters, const FingerMesh &mesh,
                           const MPI_Comm group, std::ostream &log)
    : prm(without_obstacles(parameters))
    , solver(prm, mesh.triangulation, mesh.material_names, mesh.springs, mesh.sheets, group,
             log)
    , nodes(solver.space())
    , base(solver.space())
    , rest_volume(solver.pressure_load().has_cavity() ?
                    solver.pressure_load().cavity_volume(solver.displacement()) :
                    0.0)
  {}

  double SampleGroup::first_step(const data::Actuation *start, const data::Actuation &target) const
  {
    if (target.tip_motion) // from the anchor (no motion) or the previous motion
      {
        data::TipMotion increment = *target.tip_motion;
        if (start && start->tip_motion)
          for (unsigned int c = 0; c < 3; ++c)
            {
              increment.translation[c] -= start->tip_motion->translation[c];
              increment.rotation[c] -= start->tip_motion->rotation[c];
            }
        const double step = motion_size(increment);
        return step > 0 ? std::min(1.0, prm.solver.initial_load_step * motion_size(target.tip_motion) / step) : 1.0;
      }
    // From an inflated state without forces (a chain's start) the forces grow from zero.
    if (!start || (!start->point_forces.empty() &&
                   start->point_forces.size() != target.point_forces.size()))
      return prm.solver.initial_load_step;
    data::Actuation increment = target; // the forces at the same points, in chain order
    increment.pressure -= start->pressure;
    for (std::size_t k = 0; k < start->point_forces.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        increment.point_forces[k].force[c] -= start->point_forces[k].force[c];
    const double step = load_size(increment);
    return step > 0 ? std::min(1.0, prm.solver.initial_load_step * load_size(target) / step) : 1.0;
  }

  void SampleGroup::check_samples(const std::vector<Sample> &samples)
  {
    for (const auto &sample : samples)
      if ((sample.actuation.pressure != 0.0 || sample.actuation.cavity_volume_ratio) &&
          !solver.pressure_load().has_cavity())
        throw data::InputError(prm.file + ": subsection 'Samples', sample '" + sample.label +
                               "': a pressure or cavity volume needs the mesh's physical group "
                               "'cavity', and this mesh has none");
    for (const auto &sample : samples)
      if (!sample.actuation.point_forces.empty())
        EmbeddedPoints(solver.space(), points_of(sample.actuation),
                       prm.file + ": subsection 'Samples', sample '" + sample.label +
                         "': force point");
    for (const auto &sample : samples)
      if (!sample.actuation.obstacles.empty())
        {
          solver.set_contact(prm.contact.with(sample.actuation.obstacles));
          solver.obstacle_contact()->check_rest_state(prm.file);
        }
    solver.set_contact(prm.contact);
  }

  // Volume control from the current state (rest, or the start sample's
  // state at its pressure) to the cavity volume `target`; `pressure` becomes
  // the pressure reached. The outcome in the terms of a pressure-controlled
  // solve: the load factor is the fraction of the volume increment reached.
  QuasiStaticSolver::Result SampleGroup::inflate(const double target, double &pressure)
  {
    const auto                start = std::chrono::steady_clock::now();
    VolumeControlledInflation inflation(solver, prm, solver.load_state().pressure);
    const double              v_start = inflation.volume();
    const auto                outcome = inflation.solve(target);
    QuasiStaticSolver::Result result;
    result.converged           = outcome.converged;
    result.failure             = outcome.converged ? QuasiStaticSolver::Failure::none :
                                                     QuasiStaticSolver::Failure::not_converged;
    result.reason              = outcome.reason;
    result.load_factor_reached = (outcome.curve.back().volume - v_start) / (target - v_start);
    result.newton_iterations   = outcome.newton_iterations;
    result.load_steps          = outcome.curve.size() - 1;
    result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    pressure         = inflation.pressure();
    return result;
  }

  // Load control of forces at a fixed pressure hands over to displacement
  // control (pass_force_limit) once a cut step falls below 1 % of the path:
  // steps that small are what a limit point of the forces (a sideways
  // buckling) leaves it, and each failed attempt there costs up to Solver/
  // Maximum Newton iterations. P10 pushed sideways from 0.5 to 0.7 N at
  // 0 kPa (fibre sheets, 4 mm across, 8 mm along) crept in load steps of
  // 1e-2 to 6e-5 from 0.552 to 0.557 N before Solver/Minimum load step
  // gave up: 250 Newton iterations in all, 175 with the handover, the same
  // state. Other paths keep Minimum load step.
  double SampleGroup::smallest_load_step(const LoadState &target) const
  {
    return DisplacementControlledForces::applies(solver.load_state(), target) ?
             std::max(prm.solver.min_load_step, 1e-2) :
             prm.solver.min_load_step;
  }

  // A force sample whose load control failed, from the last state it
  // converged at: by displacement control, which follows the finger past a
  // limit point of the forces (a sideways buckling). `failed` is the load
  // control's outcome; `record` receives where the limit point lay (its
  // force_limit and reason).
  QuasiStaticSolver::Result SampleGroup::pass_force_limit(const LoadState                 &target,
                                                          const QuasiStaticSolver::Result &failed,
                                                          data::SampleRecord              &record)
  {
    if (!DisplacementControlledForces::applies(solver.load_state(), target))
      return failed;
    const auto                   start = std::chrono::steady_clock::now();
    DisplacementControlledForces control(solver, prm, target);
    const auto                   outcome = control.solve();
    QuasiStaticSolver::Result    result  = failed;
    result.converged = outcome.converged;
    result.failure   = outcome.converged ? QuasiStaticSolver::Failure::none : failed.failure;
    result.reason    = outcome.converged ? "" : failed.reason + "; then " + outcome.reason;
    // The path went on from load factor r towards the target: the stored
    // state lies at r + (1 - r) mu / F (below r where the forces fell past
    // the limit).
    result.load_factor_reached += (1.0 - failed.load_factor_reached) * outcome.reached_fraction;
    result.newton_iterations += outcome.newton_iterations;
    result.load_steps += outcome.load_steps;
    result.wall_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream how;
    how << std::setprecision(3);
    if (outcome.converged && outcome.limit_force)
      {
        how << "passed a limit point of the forces at " << *outcome.limit_force
            << " N by displacement control";
        record.force_limit = *outcome.limit_force;
      }
    else if (outcome.converged)
      how << "solved by displacement control after load control failed (" << failed.reason << ')';
    record.reason = how.str();
    return result;
  }

  data::SampleRecord SampleGroup::solve(const Sample &sample, const data::SampleRecord *start,
                                        const data::SampleRecord *anchor, const unsigned int index)
  {
    solver.set_contact(prm.contact.with(sample.actuation.obstacles));
    if (sample.actuation.tip_motion)
      {
        if (!anchor)
          throw data::InputError("sample '" + sample.label + "' (" + sample.id +
                                 "): a tip motion needs the equilibrium it starts from");
        solver.set_state(nodes.displacement(anchor->x), load_of(anchor->actuation));
        solver.anchor_tip_motion(sample.actuation.tip_motion->point_contact);
      }
    if (start)
      solver.set_state(nodes.displacement(start->x), load_of(start->actuation));
    else
      solver.reset();
    data::SampleRecord record;
    record.id        = sample.id;
    record.actuation = sample.actuation;
    const LoadState target = load_of(sample.actuation);
    auto            result =
      sample.actuation.cavity_volume_ratio ?
        inflate(*sample.actuation.cavity_volume_ratio * rest_volume, record.actuation.pressure) :
        solver.solve(target, first_step(start ? &start->actuation : nullptr, sample.actuation),
                     smallest_load_step(target));
    if (!result.converged && !sample.actuation.cavity_volume_ratio)
      result = pass_force_limit(target, result, record);
    record.status = result.converged ? data::SampleStatus::converged :
                    result.failure == QuasiStaticSolver::Failure::limit_point ?
                                       data::SampleStatus::limit_point :
                                       data::SampleStatus::failed;
    record.reason              = result.converged ? record.reason :
                                   result.reason + (start ? " (load path from sample " + start->id + ")" :
                                                            " (load path from rest)");
    record.load_factor_reached = result.load_factor_reached;
    record.newton_iterations   = result.newton_iterations;
    record.load_steps          = result.load_steps;
    record.wall_time           = result.wall_time;
    record.x                   = nodes.deformed_nodes(solver.displacement());
    if (!sample.actuation.point_forces.empty())
      for (const auto &p : solver.deformed_points(points_of(sample.actuation)))
        record.force_points_deformed.push_back({{p[0], p[1], p[2]}});
    const auto wrench  = base.wrench(solver.support_forces());
    record.base_force  = {{wrench.force[0], wrench.force[1], wrench.force[2]}};
    record.base_moment = {{wrench.moment[0], wrench.moment[1], wrench.moment[2]}};
    if (const ObstacleContact *contact = solver.obstacle_contact())
      for (const auto &w : contact->obstacle_wrenches(solver.displacement(), solver.load_state().obstacle_motion))
        record.obstacle_wrenches.push_back({triple(w.force), triple(w.moment)});
    if (prm.output.write_vtu)
      SolutionOutput(prm.design.output_directory + "/" + data::folder::vtu, prm.output.subdivisions)
        .write(solver, "sample_" + sample.id, index);
    return record;
  }
} // namespace softchain::fem
