#include <softchain/fem/blas_kernel.h>

#include <deal.II/base/multithread_info.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace softchain::fem
{
  namespace
  {
    // OpenBLAS's name of the kernel it loaded, or "" if the BLAS in this
    // process is not OpenBLAS.
    std::string openblas_core()
    {
      using CoreName = char *(*)();
      const auto core_name =
        reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
      return core_name ? core_name() : "";
    }

    // The best of OpenBLAS's x86-64 kernels this CPU runs (AVX-512 needs
    // the F, CD, BW, DQ and VL subsets, as OpenBLAS's SkylakeX kernels use
    // them), or "" if none beats Prescott.
    const char *kernel_for_this_cpu()
    {
      __builtin_cpu_init();
      if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
          __builtin_cpu_supports("avx512vl"))
        return "SkylakeX";
      if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return "Haswell";
      return "";
    }
  } // namespace

  void use_the_cpus_blas_kernel(char **argv)
  {
    if (std::getenv("OPENBLAS_CORETYPE") || openblas_core() != "Prescott")
      return;
    const std::string kernel = kernel_for_this_cpu();
    if (kernel.empty())
      return;
    // The variable is set before the restart, so the restarted process
    // returns above: one restart at most.
    setenv("OPENBLAS_CORETYPE", kernel.c_str(), 1);
    execv("/proc/self/exe", argv);
  }

  void limit_threads(const unsigned int limit)
  {
    if (limit > 0)
      dealii::MultithreadInfo::set_thread_limit(limit);
    using SetThreads = void (*)(int);
    if (const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(static_cast<int>(dealii::MultithreadInfo::n_threads()));
  }
} // namespace softchain::fem
