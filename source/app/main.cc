// softchain: the command line of the three-tier pipeline
// (docs/conventions.md, "Command line and exit codes").
#include <softchain/chain/chain_run.h>
#include <softchain/chain/simulate_run.h>
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
  using namespace softchain;

  // What a command gets: the .prm, read once, and the command line's flags.
  struct Invocation
  {
    const data::PrmFile &file;
    int                  argc;
    char               **argv;

    bool has_flag(const char *flag) const
    {
      for (int k = 3; k < argc; ++k)
        if (std::strcmp(argv[k], flag) == 0)
          return true;
      return false;
    }
    // The word after `option` ("" if absent); InputError if nothing follows it.
    std::string option_value(const char *option) const
    {
      for (int k = 3; k < argc; ++k)
        if (std::strcmp(argv[k], option) == 0)
          {
            if (k + 1 == argc)
              throw data::InputError(std::string(option) + " needs a value");
            return argv[k + 1];
          }
      return "";
    }
    // Design/Output directory and the database in it, for the tiers that
    // read only their own subsections and Design (they work on any
    // database in the layout).
    data::DesignParameters design() const { return data::DesignParameters::read(file); }
  };

  // The command table: name, one line for the usage, the text of
  // `softchain help NAME`, and what it runs.
  struct Command
  {
    const char *name;
    const char *summary;
    const char *help;
    int (*run)(const Invocation &);
  };

  const Command commands[] = {
    {"solve", "FEM solve of the .prm's Loads; VTU output for ParaView",
     "softchain solve FILE.prm\n"
     "  One quasi-static FEM solve of subsection Loads (Pressure, Point loads,\n"
     "  Tip traction, Gravity, Tip motion) on the mesh of subsection Mesh, with the\n"
     "  obstacles of subsection Contact (Obstacles in solve). Writes\n"
     "  <output>/vtu/solution.pvd (open in ParaView) and <output>/solve_summary.csv.\n"
     "  Runs unchanged under mpirun -np N.\n",
     [](const Invocation &i) { return app::solve_command(i.file); }},
    {"sweep", "FEM solves of the .prm's Samples into the database (cached, resumable)",
     "softchain sweep FILE.prm\n"
     "  Every sample of subsection Samples (pressure sweep, lateral and torsion\n"
     "  force sweeps, validation and contact samples) into <output>/database.h5.\n"
     "  Samples already stored for this design are not solved again; Ctrl-C or a\n"
     "  crash keeps the completed samples and a rerun resumes. Exit 2 names failed samples.\n",
     [](const Invocation &i) { return app::sweep_command(i.file); }},
    {"reduce", "joint rotations (M1, M2), torques and stiffness CSVs from the database",
     "softchain reduce FILE.prm\n"
     "  Joint rotations (M1, M2 for each slab half-width b), torques and the\n"
     "  per-joint stiffness from <output>/database.h5 into <output>/stiffness/\n"
     "  (CSV and PNG), and the contact samples' forces into <output>/contact/.\n"
     "  Subsection Reduction; see reduction/README.md.\n",
     [](const Invocation &i) {
       const auto design = i.design();
       return reduction::run_reduction(i.file, design.database_path(), design.output_directory);
     }},
    {"chain", "kinematic-chain finger with the extracted stiffness, validated against\n"
              "           the FEM tip poses; --export-mjcf also writes a MuJoCo model",
     "softchain chain FILE.prm [--export-mjcf]\n"
     "  The kinematic-chain finger with the stiffness of subsection Chain, solved\n"
     "  for every database sample and compared with the FEM tip pose:\n"
     "  <output>/chain/validation*.csv, validation.png, fem_tip_poses.csv;\n"
     "  --export-mjcf writes a MuJoCo model (<output>/chain/finger.xml) with the\n"
     "  chain's pressure tables, and compares MuJoCo set from them with the chain\n"
     "  at 11 pressures from 0 to the largest; the last line is the largest tip\n"
     "  distance. See chain/README.md.\n",
     [](const Invocation &i) {
       const auto design = i.design();
       return chain::run_chain(i.file, design.database_path(), design.output_directory,
                               i.has_flag("--export-mjcf"));
     }},
    {"simulate", "MuJoCo scene of the exported finger and an obstacle of Contact under a\n"
                 "           slow pressure ramp; its contact force against the FEM's",
     "softchain simulate FILE.prm [--scene NAME]\n"
     "  The finger of <output>/chain/finger.xml (softchain chain --export-mjcf) in\n"
     "  MuJoCo with the obstacle NAME of subsection Contact (default: the first, or\n"
     "  none) under a slow pressure ramp through that obstacle's contact-sample\n"
     "  pressures (<output>/contact/contact_forces.csv). Writes <output>/simulate/:\n"
     "  the scene's MJCF, time series of joint angles, tip pose and contact force,\n"
     "  and contact_vs_fem.csv, MuJoCo's steady contact force against the FEM's.\n"
     "  See chain/README.md, \"MuJoCo scenes\".\n",
     [](const Invocation &i) {
       const auto design = i.design();
       return chain::run_simulate(i.file, design.database_path(), design.output_directory,
                                  i.option_value("--scene"));
     }},
    {"accuracy", "the FEM's discretisation error of the design: Loads on its mesh\n"
                 "           against the converged answer estimated from finer meshes",
     "softchain accuracy FILE.prm\n"
     "  Solves subsection Loads on the design's own mesh and model, then with the\n"
     "  fibres as sheets and two hexahedra across the walls on three meshes (the\n"
     "  design's element size times 1, 0.71 and 0.5). A Richardson extrapolation of\n"
     "  the mean tip displacement over those three estimates the mesh-converged\n"
     "  answer and its uncertainty; the last line is the design's distance to it\n"
     "  in % of its length. Writes <output>/fem_accuracy.csv, which the report's\n"
     "  summary shows while the design is unchanged (the table names its design\n"
     "  hash). Parametric designs with Element shape = hex, Control =\n"
     "  pressure. See docs/fem_accuracy.md.\n",
     [](const Invocation &i) { return app::accuracy_command(i.file); }},
    {"run", "the whole pipeline: sweep, reduce, chain, report; lists the output files",
     "softchain run FILE.prm\n"
     "  sweep, reduce, chain and report in one go, one progress line per stage and\n"
     "  sample, and the list of every output file with what it is.\n",
     [](const Invocation &i) { return app::run_command(i.file); }},
    {"report", "report.html (one self-contained page) from the outputs of a run",
     "softchain report FILE.prm\n"
     "  Rebuilds <output>/report.html from the outputs of an earlier run\n"
     "  (database.h5, stiffness/, chain/, contact/): the design, pictures of the\n"
     "  deformed finger at 0, 40 and 80 kPa, the stiffness plots and tables, the chain\n"
     "  validation, the contact samples, per-sample solve times and the paper's claims\n"
     "  with verdicts. One self-contained HTML file. Stage times are only known to\n"
     "  `softchain run`.\n",
     [](const Invocation &i) {
       const auto design = i.design();
       return report::run_report(i.file, design.database_path(), design.output_directory);
     }},
  };

  const Command *find_command(const std::string &name)
  {
    for (const Command &c : commands)
      if (name == c.name)
        return &c;
    return nullptr;
  }

  std::string usage()
  {
    std::string text = "usage: softchain COMMAND FILE.prm [--export-mjcf | --scene NAME]\n\ncommands:\n";
    for (const Command &c : commands)
      text += "  " + std::string(c.name) + std::string(9 - std::strlen(c.name), ' ') + c.summary + "\n";
    return text + "  help     this text; help COMMAND (or COMMAND --help): that command in detail\n"
                  "\n"
                  "Outputs go to the .prm's Design/Output directory (default output/<name>/):\n"
                  "database.h5, vtu/, stiffness/, contact/, chain/, simulate/, report.html.\n"
                  "Exit status: 0 success, 1 bad input, 2 a solve or sample did not converge.\n";
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

} // namespace

int main(int argc, char **argv)
{
  softchain::fem::use_the_cpus_blas_kernel(argv);
  softchain::fem::use_no_network_transport_when_alone();
  // deal.II's thread pool (the cell assembly's WorkStream) gets the cores
  // not taken by other MPI ranks on this node, and OpenBLAS as many;
  // Solver/Threads may lower both.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  softchain::fem::limit_threads(0);
  std::signal(SIGINT, on_interrupt);
  const std::string command = argc > 1 ? argv[1] : "help";
  const bool        help    = command == "help" || command == "--help" || command == "-h";
  const std::string second  = argc > 2 ? argv[2] : "";
  const Command    *asked   = find_command(help ? second : command);
  if (asked && (help || second == "--help" || second == "-h"))
    {
      std::cout << asked->help;
      return 0;
    }
  if (help)
    {
      std::cout << usage();
      return 0;
    }
  if (!asked)
    {
      std::cerr << "softchain: unknown command '" << command << "'\n" << usage();
      return 1;
    }
  if (argc < 3)
    {
      std::cerr << "softchain: " << command << " needs a .prm file\n" << asked->help;
      return 1;
    }
  try
    {
      const data::PrmFile file = data::PrmFile::read(argv[2]);
      return asked->run({file, argc, argv});
    }
  catch (const data::InputError &e)
    {
      std::cerr << "softchain: error: " << e.what() << '\n';
      return 1;
    }
}
