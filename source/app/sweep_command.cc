// `softchain sweep FILE.prm`: the sample sweep into <output dir>/database.h5.
#include <softchain/app/commands.h>
#include <softchain/fem/sample_sweep.h>

#include <deal.II/base/mpi.h>

#include <iostream>

namespace softchain::app
{
  using namespace dealii;
  using namespace softchain::fem;

  int sweep_command(const data::PrmFile &prm_file)
  {
    const bool   root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    std::ostream silent(nullptr);
    return SampleSweep(prm_file).run().report(root ? std::cout : silent,
                                              root ? std::cerr : silent);
  }
} // namespace softchain::app
