// Catch2 main of the FEM-tier tests: MPI (and deal.II's thread pool) set up
// around the Catch2 run, so the same tests run under mpirun.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <softchain/fem/blas_kernel.h>
#include <softchain/fem/lone_process_mpi.h>

#include <deal.II/base/mpi.h>

int main(int argc, char **argv)
{
  softchain::fem::use_the_cpus_blas_kernel(argv);
  softchain::fem::use_no_network_transport_when_alone();
  // Threads as in `softchain`: the cell assembly runs in parallel here too.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  return Catch::Session().run(argc, argv);
}
