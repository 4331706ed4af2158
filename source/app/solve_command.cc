// `softchain solve FILE.prm`: one quasi-static solve of the .prm's Loads,
// written as VTU for ParaView, with a timing summary.
#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/base_reaction.h>
#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/app/commands.h>
#include <softchain/app/solve_loads.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/quasi_static_solver.h>
#include <softchain/fem/solution_output.h>
#include <softchain/fem/volume_controlled_inflation.h>

#include <deal.II/base/conditional_ostream.h>

#include <chrono>
#include <iostream>
#include <tuple>

namespace softchain::app
{
  using namespace dealii;
  using namespace softchain::fem;

  namespace
  {
    // <output directory>/solve_summary.csv, one header and one data row, 17
    // significant digits (doubles round-trip), written by rank 0: the
    // machine-readable result that tests compare between runs.
    void write_summary(const std::string &directory, const QuasiStaticSolver::Result &result,
                       const Tensor<1, 3> &tip, const double cavity_volume,
                       const BaseReaction::Wrench &base, const double cavity_pressure,
                       const std::vector<std::string>            &obstacle_names,
                       const std::vector<ObstacleContact::Wrench> &obstacles)
    {
      std::vector<std::string> columns{"converged", "load_factor", "newton_iterations", "load_steps",
                                       "tip_displacement_x", "tip_displacement_y", "tip_displacement_z",
                                       "cavity_volume", "base_force_x", "base_force_y", "base_force_z",
                                       "base_moment_x", "base_moment_y", "base_moment_z",
                                       "cavity_pressure"};
      std::vector<double> row{double(result.converged), result.load_factor_reached,
                              double(result.newton_iterations),
                              double(result.load_steps), tip[0], tip[1], tip[2],
                              cavity_volume, base.force[0], base.force[1],
                              base.force[2], base.moment[0], base.moment[1],
                              base.moment[2], cavity_pressure};
      // Per obstacle: the force and the moment about the origin it receives.
      for (std::size_t k = 0; k < obstacles.size(); ++k)
        for (const auto &[quantity, value] : {std::pair{"force", obstacles[k].force},
                                              std::pair{"moment", obstacles[k].moment}})
          for (unsigned int i = 0; i < 3; ++i)
            {
              columns.push_back(obstacle_names[k] + "_" + quantity + "_" + "xyz"[i]);
              row.push_back(value[i]);
            }
      data::CsvTable summary(columns);
      summary.add_row(row);
      summary.write(directory + "/solve_summary.csv");
    }

    // Control = volume: inflates the cavity to Cavity volume ratio times its
    // volume at rest, the pressure solved for; writes the pressure-volume
    // curve of the converged steps to <output>/pressure_volume.csv. Returns
    // the solve's counts and the pressure reached.
    std::pair<QuasiStaticSolver::Result, double>
    inflate_to_volume(QuasiStaticSolver &solver, const Parameters &prm, std::ostream &out)
    {
      const auto                start = std::chrono::steady_clock::now();
      VolumeControlledInflation inflation(solver, prm);
      const double              rest_volume = inflation.volume();
      const auto                inflated    = inflation.solve(prm.loads.volume_ratio * rest_volume);
      QuasiStaticSolver::Result result;
      result.converged           = inflated.converged;
      result.reason              = inflated.reason;
      result.newton_iterations   = inflated.newton_iterations;
      result.load_steps          = inflated.curve.size() - 1;
      const double wanted        = (prm.loads.volume_ratio - 1) * rest_volume;
      result.load_factor_reached = wanted != 0 ? (inflation.volume() - rest_volume) / wanted : 1.0;
      result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      data::CsvTable curve({"cavity_volume", "volume_ratio", "cavity_pressure"});
      for (const auto &point : inflated.curve)
        curve.add_row(std::vector<double>{point.volume, point.volume / rest_volume, point.pressure});
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        curve.write(prm.design.output_directory + "/pressure_volume.csv");
      out << "volume control: cavity volume " << rest_volume << " -> " << inflation.volume()
          << " m^3, pressure " << inflation.pressure() << " Pa (the curve: "
          << prm.design.output_directory << "/pressure_volume.csv)\n";
      return {result, inflation.pressure()};
    }
  } // namespace

  int solve_command(const data::PrmFile &prm_file)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    ConditionalOStream out(std::cout, Utilities::MPI::this_mpi_process(comm) == 0);
    Parameters         prm = Parameters::read(prm_file);
    prm.contact            = prm.contact.solve_scene(); // the obstacles of Obstacles in solve
    limit_threads(prm.solver.threads);

    FingerMesh mesh;
    FingerMesh::build(prm, mesh);
    QuasiStaticSolver solver(prm, mesh.triangulation, mesh.material_names, mesh.springs, mesh.sheets, comm,
                             out.get_stream());
    out << "softchain solve: " << prm.design.name << " (" << mesh.description << "), "
        << name(prm.mesh.element_type) << ", " << solver.space().triangulation.n_global_active_cells()
        << " cells, " << solver.space().dof_handler.n_dofs() << " DoFs, "
        << Utilities::MPI::n_mpi_processes(comm) << " rank(s)\n";

    if (solver.obstacle_contact())
      solver.obstacle_contact()->check_rest_state(prm.file);
    const bool by_volume = prm.loads.control == LoadParameters::Control::volume;
    if ((prm.loads.pressure != 0.0 || by_volume) && !solver.pressure_load().has_cavity())
      throw data::InputError(prm.file + ": parameter '" + (by_volume ? "Control" : "Pressure") +
                             "' in subsection 'Loads': a pressure needs the mesh's physical group "
                             "'cavity', and " + mesh.description + " has none");
    QuasiStaticSolver::Result result;
    double                    cavity_pressure = prm.loads.pressure;
    if (by_volume)
      std::tie(result, cavity_pressure) = inflate_to_volume(solver, prm, out.get_stream());
    else
      {
        result          = solve_loads(solver, prm, out.get_stream());
        cavity_pressure = solver.load_state().pressure;
      }

    const Tensor<1, 3> tip = mean_boundary_displacement(solver.space(), solver.displacement(),
                                                        boundary::tip);
    out << (result.converged ? "converged" : "FAILED: " + result.reason) << " after "
        << result.load_steps << " load steps, " << result.newton_iterations
        << " Newton iterations, " << result.wall_time << " s\n"
        << "mean tip displacement [m]: " << tip << '\n';
    const double cavity_volume = solver.pressure_load().cavity_volume(solver.displacement());
    const BaseReaction         base(solver.space());
    const BaseReaction::Wrench wrench = base.wrench(solver.support_forces());
    out << "base wrench (on the support, about the base centroid " << base.centroid()
        << "): force [N] " << wrench.force << ", moment [N m] " << wrench.moment << '\n';
    std::vector<std::string>             obstacle_names;
    std::vector<ObstacleContact::Wrench> obstacles;
    if (const ObstacleContact *contact = solver.obstacle_contact())
      {
        obstacles = contact->obstacle_wrenches(solver.displacement(), solver.load_state().obstacle_motion);
        for (std::size_t k = 0; k < obstacles.size(); ++k)
          {
            obstacle_names.push_back(prm.contact.obstacles[k].name());
            out << "obstacle " << obstacle_names[k] << " receives force [N] " << obstacles[k].force
                << ", moment about the origin [N m] " << obstacles[k].moment << '\n';
          }
        out << "deepest contact penetration: "
            << contact->deepest_penetration(solver.displacement(), solver.load_state().obstacle_motion)
            << " of the local face size\n";
      }
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_summary(prm.design.output_directory, result, tip, cavity_volume, wrench,
                    cavity_pressure, obstacle_names, obstacles);
    if (prm.output.write_vtu)
      {
        TimerOutput::Scope timer_section(solver.timer(), "output");
        SolutionOutput output(prm.design.output_directory + "/" + data::folder::vtu, prm.output.subdivisions);
        out << "wrote " << prm.design.output_directory << "/" << data::folder::vtu << "/"
            << output.write(solver, "solution", result.load_factor_reached) << '\n';
      }
    solver.timer().print_summary();
    return result.converged ? 0 : 2;
  }
} // namespace softchain::app
