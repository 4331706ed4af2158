// softchain: the command line of the three-tier pipeline
// (ARCHITECTURE.md, "Command line").
#include <softchain/chain/chain_run.h>
#include <softchain/commands.h>
#include <softchain/data/input_error.h>
#include <softchain/parameters.h>
#include <softchain/reduction/reduction_run.h>

#include <deal.II/base/mpi.h>

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
    "  run      the whole pipeline: sweep, reduce, chain; lists the output files\n"
    "  help     this text\n"
    "\n"
    "Outputs go to the .prm's Design/Output directory (default output/<name>/):\n"
    "database.h5, vtu/, stiffness/, chain/.\n"
    "Exit status: 0 success, 1 bad input, 2 a solve or sample did not converge.\n";

  bool has_flag(int argc, char **argv, const char *flag)
  {
    for (int k = 3; k < argc; ++k)
      if (std::strcmp(argv[k], flag) == 0)
        return true;
    return false;
  }

  int run(const std::string &command, const std::string &file, int argc, char **argv)
  {
    using namespace softchain;
    if (command == "solve")
      return solve_command(file);
    if (command == "sweep")
      return sweep_command(file);
    if (command == "run")
      return run_command(file);
    const Parameters  prm       = Parameters::read(file);
    const std::string directory = prm.design.output_directory;
    if (command == "reduce")
      return reduction::run_reduction(file, directory + "/database.h5", directory);
    if (command == "chain")
      return chain::run_chain(file, directory + "/database.h5", directory,
                              has_flag(argc, argv, "--export-mjcf"));
    std::cerr << "softchain: unknown command '" << command << "'\n" << usage;
    return 1;
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string command = argc > 1 ? argv[1] : "help";
  const bool        help    = command == "help" || command == "--help" || command == "-h";
  if (help || argc < 3)
    {
      std::cout << usage;
      return help ? 0 : 1;
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
