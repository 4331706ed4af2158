// `softchain accuracy FILE.prm`: how far the design's FEM answer lies from
// the mesh-converged finger. The design's Loads are solved on its own mesh
// and model, then with the fibres as sheets (the model with a converged
// answer) and two elements across the walls on three meshes, the design's
// element size times 1, 1/sqrt(2) and 1/2. A Richardson extrapolation of the
// mean tip displacement over those three (data::RichardsonExtrapolation)
// estimates the converged answer and its uncertainty; the design's distance
// to it, in % of the finger's length, is its discretisation error
// (docs/fem_accuracy.md).
#include <softchain/app/commands.h>
#include <softchain/app/solve_loads.h>
#include <softchain/data/content_hash.h>
#include <softchain/data/csv_table.h>
#include <softchain/data/input_error.h>
#include <softchain/data/richardson_extrapolation.h>
#include <softchain/fem/boundary_average.h>
#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/design_hash.h>
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/quasi_static_solver.h>

#include <deal.II/base/conditional_ostream.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace softchain::app
{
  using namespace dealii;
  using namespace softchain::fem;

  namespace
  {
    // One mesh and reinforcement of the design.
    struct Discretisation
    {
      std::string name;
      double      mesh_size;
      double      mesh_size_along; // along the finger (0: mesh_size)
      int         wall_layers;
      bool        sheets;
    };

    struct Solved
    {
      Discretisation     discretisation;
      unsigned int       dofs;
      double             wall_time;
      bool               converged;
      Tensor<1, 3>       tip; // mean tip displacement, m
      std::string        design_hash; // of its mesh and model (fem::design_hash)
    };

    Solved solve(const Parameters &prm, const Discretisation &d, ConditionalOStream &out)
    {
      Parameters variant = prm;
      variant.finger_design->mesh_sizes[variant.finger_design->resolution]       = d.mesh_size;
      variant.finger_design->mesh_sizes_along[variant.finger_design->resolution] = d.mesh_size_along;
      variant.finger_design->wall_layers  = d.wall_layers;
      variant.finger_design->fibre_sheets = d.sheets;
      FingerMesh mesh;
      FingerMesh::build(variant, mesh);
      std::ostringstream log;
      QuasiStaticSolver  solver(variant, mesh.triangulation, mesh.material_names, mesh.springs,
                                mesh.sheets, MPI_COMM_WORLD, log);
      const auto result = solve_loads(solver, variant, log);
      const Solved solved{d, static_cast<unsigned int>(solver.space().dof_handler.n_dofs()),
                          result.wall_time, result.converged,
                          mean_boundary_displacement(solver.space(), solver.displacement(), boundary::tip),
                          design_hash(variant, mesh)};
      out << "  " << d.name << ": " << 1e3 * d.mesh_size << " mm";
      if (d.mesh_size_along > 0)
        out << " (" << 1e3 * d.mesh_size_along << " mm along the finger)";
      out << ", " << d.wall_layers
          << " across the walls, " << solved.dofs << " DoFs, "
          << (result.converged ? "converged" : "FAILED: " + result.reason) << ", " << result.wall_time
          << " s, tip displacement [mm] " << 1e3 * solved.tip << '\n';
      return solved;
    }

    // The converged tip displacement from the three sheet runs (runs 1 to 3,
    // coarsest first), per component, with h = DoFs^(-1/3). A component that
    // the loads leave at rest on every mesh (below 1e-9 of the length: a
    // symmetric finger's z) has nothing to extrapolate.
    struct Estimate
    {
      Tensor<1, 3> tip;
      double       uncertainty = 0; // m
      double       order       = 0; // the largest observed
      bool         asymptotic  = true;
    };

    Estimate converged_estimate(const std::vector<Solved> &runs, const double length)
    {
      std::array<double, 3> sizes;
      for (int k = 0; k < 3; ++k)
        sizes[k] = std::cbrt(1.0 / runs[3 - k].dofs);
      Estimate estimate;
      double   uncertainty_squared = 0;
      for (unsigned int c = 0; c < 3; ++c)
        {
          const std::array<double, 3> f{{runs[3].tip[c], runs[2].tip[c], runs[1].tip[c]}};
          estimate.tip[c] = f[0];
          if (std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])}) < 1e-9 * length)
            continue;
          const auto r    = data::RichardsonExtrapolation::of(sizes, f);
          estimate.tip[c] = r.value;
          uncertainty_squared += r.uncertainty * r.uncertainty;
          estimate.asymptotic = estimate.asymptotic && r.asymptotic;
          estimate.order      = std::max(estimate.order, r.order);
        }
      estimate.uncertainty = std::sqrt(uncertainty_squared);
      return estimate;
    }

    // <output>/fem_accuracy.csv (rank 0): one row per run with its distance
    // to the estimate, then the estimate with its uncertainty (% of L). Each
    // run names its design hash; the first, the design's own, is the hash of
    // the database `softchain sweep` writes for this .prm, by which the
    // report knows whether the table is of the design it reports on.
    void write_table(const std::string &csv, const std::vector<Solved> &runs, const Estimate &estimate,
                     const double length)
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      const auto mm = [](double v) { return data::canonical(1e3 * v); };
      data::CsvTable table({"run", "mesh_size_mm", "wall_layers", "reinforcement", "dofs", "wall_time_s",
                            "tip_dx_mm", "tip_dy_mm", "tip_dz_mm", "distance_to_converged_percent_L",
                            "design_hash"});
      for (const Solved &run : runs)
        table.add_row({run.discretisation.name, mm(run.discretisation.mesh_size),
                       std::to_string(run.discretisation.wall_layers),
                       run.discretisation.sheets ? "sheets" : "springs", std::to_string(run.dofs),
                       data::canonical(run.wall_time), mm(run.tip[0]), mm(run.tip[1]), mm(run.tip[2]),
                       data::canonical((run.tip - estimate.tip).norm() * 100 / length), run.design_hash});
      table.add_row({estimate.asymptotic ? "converged (Richardson)" : "converged (finest run)", "", "",
                     "sheets", "", "", mm(estimate.tip[0]), mm(estimate.tip[1]), mm(estimate.tip[2]),
                     data::canonical(estimate.uncertainty * 100 / length), ""});
      std::filesystem::create_directories(std::filesystem::path(csv).parent_path());
      table.write(csv);
    }

    void check_design(const Parameters &prm)
    {
      const auto refuse = [&](const std::string &why) {
        throw data::InputError(prm.file + ": softchain accuracy " + why);
      };
      if (!prm.finger_design || !prm.finger_design->parametric())
        refuse("needs a parametric design (Mesh/Source = finger design, Finger design/Shape p10, p13 "
               "or parallelepiped): it refines the design's mesh");
      if (!prm.finger_design->hexahedra)
        refuse("needs Finger design/Element shape = hex (the layers across the walls are hexahedra)");
      if (prm.loads.control != LoadParameters::Control::pressure)
        refuse("solves Loads under Control = pressure");
    }
  } // namespace

  int accuracy_command(const data::PrmFile &file)
  {
    ConditionalOStream out(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    Parameters         prm = Parameters::read(file);
    prm.contact            = geometry::ContactScene(); // the finger alone
    check_design(prm);
    const geometry::FingerDesign &design = *prm.finger_design;
    const double                  h      = design.mesh_size();
    const double                  length = design.length();
    out << "softchain accuracy: " << prm.design.name << ", subsection Loads on the design's mesh and "
        << "on three finer ones with fibre sheets:\n";

    std::vector<Solved> runs;
    // A design with a size of its own along the finger is refined in both
    // directions by the same ratio.
    const double along = design.mesh_sizes_along[design.resolution];
    runs.push_back(solve(prm, {"design", h, along, design.wall_layers, design.fibre_sheets}, out));
    for (const double refinement : {1.0, std::sqrt(0.5), 0.5})
      runs.push_back(solve(prm, {"sheets", refinement * h, refinement * along, 2, true}, out));
    for (const Solved &run : runs)
      if (!run.converged)
        {
          out << "FAILED: the " << run.discretisation.name << " solve at "
              << 1e3 * run.discretisation.mesh_size << " mm did not converge\n";
          return 2;
        }

    const Estimate    estimate = converged_estimate(runs, length);
    const std::string csv      = prm.design.output_directory + "/fem_accuracy.csv";
    write_table(csv, runs, estimate, length);
    const double uncertainty = estimate.uncertainty * 100 / length;
    const Tensor<1, 3> &converged = estimate.tip;
    std::ostringstream how;
    how << std::setprecision(3);
    if (estimate.asymptotic)
      how << "Richardson, observed order " << estimate.order;
    else
      how << "the finest run: the meshes are not yet in the asymptotic range";
    out << std::setprecision(3) << "converged tip displacement [mm] " << 1e3 * converged << " ("
        << how.str() << "), uncertain to " << uncertainty << " % of L; table: " << csv << '\n'
        << "FEM discretisation error: " << (runs[0].tip - converged).norm() * 100 / length
        << " % of L (+- " << uncertainty << ")\n";
    return 0;
  }
} // namespace softchain::app
