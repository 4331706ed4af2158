#include <softchain/fem/lone_process_mpi.h>

#include <cstdlib>
#include <initializer_list>

namespace softchain::fem
{
  namespace
  {
    // Variables that OpenMPI's mpirun, PMIx, PMI (MPICH's Hydra) and Slurm
    // set in every process they start.
    bool started_by_a_launcher()
    {
      for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"})
        if (std::getenv(name))
          return true;
      return false;
    }
  } // namespace

  void use_no_network_transport_when_alone()
  {
    if (!started_by_a_launcher())
      setenv("OMPI_MCA_pml", "ob1", 0); // 0: a user's own choice stays
  }
} // namespace softchain::fem
