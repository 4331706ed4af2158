#pragma once
// The BLAS kernel for this CPU. MUMPS's LDL^T spends most of its time in
// DGEMM on the dense fronts, so the factorisation runs only as fast as the
// BLAS kernel OpenBLAS picked for the CPU.
//
// OpenBLAS (Debian's build carries every x86-64 kernel) picks that kernel once,
// when the library is loaded, from the CPU's family and model number. A CPU
// newer than its table, like this machine's Xeon with AVX-512 that reports
// itself as the generic "Intel(R) Xeon(R) Processor", gets the SSE3 kernel
// "Prescott". The only way to choose another one is the environment variable
// OPENBLAS_CORETYPE, read at load time: so a program that finds OpenBLAS
// on Prescott on a CPU with AVX-512 (or AVX2 and FMA) sets it to SkylakeX
// (or Haswell) and starts itself again. The P10 sample's linear solve went from
// 12.6 to 8.0 s with SkylakeX (docs/history.md, "The BLAS kernel for this CPU").
//
// A user's own OPENBLAS_CORETYPE is left alone, as is any other BLAS.

namespace softchain::fem
{
  // Call first thing in main(), before MPI starts: on a CPU that OpenBLAS
  // does not know, replaces the process by itself (same arguments) with
  // OPENBLAS_CORETYPE set; otherwise (or if that fails) returns.
  void use_the_cpus_blas_kernel(char **argv);

  // Limits deal.II's thread pool to `limit` threads (0: leaves the count
  // MPI_InitFinalize chose, the cores not taken by other ranks on the node)
  // and gives OpenBLAS as many. OpenBLAS starts a thread per core whatever
  // the MPI ranks beside it: two ranks on two cores ran four BLAS threads,
  // which took turns in a busy wait. Call after MPI starts; does nothing to
  // another BLAS.
  void limit_threads(unsigned int limit);
} // namespace softchain::fem
