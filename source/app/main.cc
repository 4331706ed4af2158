// softchain: the command line of the three-tier pipeline
// (docs/conventions.md, "Command line and exit codes").
#include <softchain/chain/chain_run.h>
#include <softchain/app/commands.h>
#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/lone_process_mpi.h>
#include <softchain/data/input_error.h>
#include <softchain/data/design_parameters.h>
#include <softchain/data/prm_file.h>
#include <softchain/reduction/reduction_run.h>
#include <softchain/report/report_run.h>

#include <deal.II/base/mpi.h>

#include <unistd.h>

#include <csignal>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "usage: softchain COMMAND FILE.prm [--export-mjcf]\n"
    "\n"
    "commands:\n"
    "  solve    FEM solve of the .prm's Loads; VTU output for ParaView\n"
    "  sweep    FEM solves of the .prm's Samples into the database (cached, resumable)\n"
    "  reduce   joint rotations (M1, M2), torques and stiffness CSVs from the database\n"
    "  chain    kinematic-chain finger with the extracted stiffness, validated against\n"
    "           the FEM tip poses; --export-mjcf also writes a MuJoCo model\n"
    "  run      the whole pipeline: sweep, reduce, chain, report; lists the output files\n"
    "  report   report.html (one self-contained page) from the outputs of a run\n"
    "  help     this text; help COMMAND (or COMMAND --help): that command in detail\n"
    "\n"
    "Outputs go to the .prm's Design/Output directory (default output/<name>/):\n"
    "database.h5, vtu/, stiffness/, chain/, report.html.\n"
    "Exit status: 0 success, 1 bad input, 2 a solve or sample did not converge.\n";

  // `softchain help COMMAND` / `softchain COMMAND --help`.
  const char *command_help(const std::string &command)
  {
    if (command == "solve")
      return "softchain solve FILE.prm\n"
             "  One quasi-static FEM solve of subsection Loads (Pressure, Point loads,\n"
             "  Tip traction, Gravity) on the mesh of subsection Mesh. Writes\n"
             "  <output>/vtu/solution.pvd (open in ParaView) and <output>/solve_summary.csv.\n"
             "  Runs unchanged under mpirun -np N.\n";
    if (command == "sweep")
      return "softchain sweep FILE.prm\n"
             "  Every sample of subsection Samples (pressure sweep, lateral and torsion\n"
             "  force sweeps, validation samples) into <output>/database.h5. Samples\n"
             "  already stored for this design are not solved again; Ctrl-C or a crash\n"
             "  keeps the completed samples and a rerun resumes. Exit 2 names failed samples.\n";
    if (command == "reduce")
      return "softchain reduce FILE.prm\n"
             "  Joint rotations (M1, M2 for each slab half-width b), torques and the\n"
             "  per-joint stiffness from <output>/database.h5 into <output>/stiffness/\n"
             "  (CSV and PNG). Subsection Reduction; see reduction/README.md.\n";
    if (command == "chain")
      return "softchain chain FILE.prm [--export-mjcf]\n"
             "  The kinematic-chain finger with the stiffness of subsection Chain, solved\n"
             "  for every database sample and compared with the FEM tip pose:\n"
             "  <output>/chain/validation*.csv, validation.png, fem_tip_poses.csv;\n"
             "  --export-mjcf writes a MuJoCo model. See chain/README.md.\n";
    if (command == "run")
      return "softchain run FILE.prm\n"
             "  sweep, reduce, chain and report in one go, one progress line per stage and\n"
             "  sample, and the list of every output file with what it is.\n";
    if (command == "report")
      return "softchain report FILE.prm\n"
             "  Rebuilds <output>/report.html from the outputs of an earlier run\n"
             "  (database.h5, stiffness/, chain/): the design, pictures of the deformed\n"
             "  finger at 0, 40 and 80 kPa, the stiffness plots and tables, the chain\n"
             "  validation, per-sample solve times and the paper's claims with verdicts.\n"
             "  One self-contained HTML file. Stage times are only known to `softchain run`.\n";
    return nullptr;
  }

  // Ctrl-C stops at once: every stored sample was written atomically (copy,
  // fsync, rename; data/README), so the database is consistent and a rerun
  // resumes from the samples it holds. Only async-signal-safe calls here.
  extern "C" void on_interrupt(int)
  {
    const char message[] = "\nsoftchain: interrupted; the database keeps every completed "
                           "sample, run the same command again to resume\n";
    [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(130);
  }

  bool has_flag(int argc, char **argv, const char *flag)
  {
    for (int k = 3; k < argc; ++k)
      if (std::strcmp(argv[k], flag) == 0)
        return true;
    return false;
  }

  // Reads the .prm once and hands it to the command; the reduction, chain
  // and report parse only their own subsections and Design (where the
  // database is), so they work on any database in the layout.
  int run(const std::string &command, const std::string &path, int argc, char **argv)
  {
    using namespace softchain;
    const data::PrmFile file = data::PrmFile::read(path);
    if (command == "solve")
      return app::solve_command(file);
    if (command == "sweep")
      return app::sweep_command(file);
    if (command == "run")
      return app::run_command(file);
    const data::DesignParameters design    = data::DesignParameters::read(file);
    const std::string           &directory = design.output_directory;
    if (command == "reduce")
      return reduction::run_reduction(file, design.database_path(), directory);
    if (command == "chain")
      return chain::run_chain(file, design.database_path(), directory,
                              has_flag(argc, argv, "--export-mjcf"));
    return report::run_report(file, design.database_path(), directory);
  }
} // namespace

int main(int argc, char **argv)
{
  softchain::fem::use_the_cpus_blas_kernel(argv);
  softchain::fem::use_no_network_transport_when_alone();
  // deal.II's thread pool (the cell assembly's WorkStream) gets the cores
  // not taken by other MPI ranks on this node; Solver/Threads may lower it.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  std::signal(SIGINT, on_interrupt);
  const std::string command = argc > 1 ? argv[1] : "help";
  const bool        help    = command == "help" || command == "--help" || command == "-h";
  const std::string second  = argc > 2 ? argv[2] : "";
  if (help && command_help(second))
    {
      std::cout << command_help(second);
      return 0;
    }
  if (command_help(command) && (second == "--help" || second == "-h"))
    {
      std::cout << command_help(command);
      return 0;
    }
  if (help)
    {
      std::cout << usage;
      return 0;
    }
  if (!command_help(command))
    {
      std::cerr << "softchain: unknown command '" << command << "'\n" << usage;
      return 1;
    }
  if (argc < 3)
    {
      std::cerr << "softchain: " << command << " needs a .prm file\n" << command_help(command);
      return 1;
    }
  try
    {
      return run(command, argv[2], argc, argv);
    }
  catch (const softchain::data::InputError &e)
    {
      std::cerr << "softchain: error: " << e.what() << '\n';
      return 1;
    }
}
