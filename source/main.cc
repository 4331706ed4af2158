// softchain: the command line of the three-tier pipeline
// (ARCHITECTURE.md, "Command line").
#include <softchain/commands.h>
#include <softchain/data/input_error.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

namespace
{
  const char *usage =
    "usage: softchain COMMAND FILE.prm [options]\n"
    "\n"
    "commands:\n"
    "  solve   FEM solve of the .prm's Loads; VTU output for ParaView\n"
    "  help    this text\n"
    "\n"
    "Outputs go to the .prm's Design/Output directory (default output/<name>/).\n"
    "Exit status: 0 success, 1 bad input, 2 a solve did not converge.\n";
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string command = argc > 1 ? argv[1] : "help";
  if (command == "help" || command == "--help" || command == "-h" || argc < 3)
    {
      std::cout << usage;
      return command == "help" || command == "--help" || command == "-h" ? 0 : 1;
    }
  try
    {
      if (command == "solve")
        return softchain::solve_command(argv[2]);
      std::cerr << "softchain: unknown command '" << command << "'\n" << usage;
      return 1;
    }
  catch (const softchain::data::InputError &e)
    {
      std::cerr << "softchain: error: " << e.what() << '\n';
      return 1;
    }
}
