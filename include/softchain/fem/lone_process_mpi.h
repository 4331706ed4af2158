#pragma once
// MPI for a process that runs alone. Started without a launcher (mpirun,
// srun), a SoftChain program is an MPI singleton: one rank, no peers to
// reach. Debian's OpenMPI then still loads its UCX transport, which probes
// the machine's network devices while MPI starts: 0.2 s of the 0.84 s that
// `softchain` took to start and stop on this project's machines (median of
// five, docs/history.md, "Starting a process"). Such a process has no use for a network
// transport, so it asks OpenMPI for its ob1 layer (shared memory and self)
// instead, unless the user set a transport (OMPI_MCA_pml) of their own. A
// process a launcher started keeps OpenMPI's choice: on a cluster that is
// the fast network.

namespace softchain::fem
{
  // Call in main() before MPI starts.
  void use_no_network_transport_when_alone();
} // namespace softchain::fem
