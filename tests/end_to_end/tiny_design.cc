#include "tiny_design.h"

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

namespace softchain::testing
{
  namespace
  {
    // mpirun refuses to run as root without the OMPI_ variables
    // (docs/toolchain.md, "MPI"). One BLAS thread and one deal.II thread per
    // process: MUMPS's dense kernels and deal.II's threaded loops round
    // differently with 2 threads (a serial run) than with 1 (a rank bound to
    // one core under mpirun), by a few ulps (each thread count alone gives
    // the same bits on every run); with the same thread count the samples of
    // 1 and 2 ranks are the same bits. Set once for every child process of
    // the tests.
    const bool environment_set = [] {
      for (const char *name : {"OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM",
                               "OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "DEAL_II_NUM_THREADS"})
        ::setenv(name, "1", 1);
      return true;
    }();

    std::string read_text(const std::string &file)
    {
      std::ifstream      in(file);
      std::ostringstream text;
      text << in.rdbuf();
      return text.str();
    }

    // What differs between two records of the same sample ("" if nothing).
    std::string record_difference(const data::SampleRecord &a, const data::SampleRecord &b)
    {
      const std::pair<bool, const char *> fields[] = {
        {a.status == b.status && a.reason == b.reason, "status"},
        {a.load_factor_reached == b.load_factor_reached, "load factor"},
        {a.newton_iterations == b.newton_iterations, "Newton iterations"},
        {a.load_steps == b.load_steps, "load steps"},
        {a.actuation.canonical_text() == b.actuation.canonical_text() &&
           a.actuation.pressure == b.actuation.pressure && a.actuation.role == b.actuation.role,
         "actuation"},
        {a.x == b.x, "x"},
        {a.force_points_deformed == b.force_points_deformed, "force_points_deformed"},
        {a.base_force == b.base_force && a.base_moment == b.base_moment, "base wrench"}};
      for (const auto &[same, name] : fields)
        if (!same)
          return "sample " + a.id + ": " + name + " differs";
      return "";
    }
  } // namespace

  TinyDesign::TinyDesign(const std::string &name, const std::string &samples,
                         const std::string &extra)
    : dir(name)
  {
    write(samples, extra);
  }

  void TinyDesign::write(const std::string &samples, const std::string &extra) const
  {
    std::ofstream(prm()) << "subsection Design\n  set Name = tiny\n  set Output directory = "
                         << output() << "\nend\n"
                         << "subsection Mesh\n  set Source = built-in bender\n"
                            "  set Element type = Q1\n  set Bender cells along length = 4\nend\n"
                         << "subsection Materials\n  subsection silicone\n"
                            "    set Young's modulus = 2.6e5\n    set Poisson's ratio = 0.48\n"
                            "  end\nend\n"
                         << "subsection Springs\n  set Generate for bender = false\nend\n"
                         << "subsection Output\n  set Write VTU = false\n  set Verbose = false\nend\n"
                         << "subsection Samples\n"
                         << samples << "\nend\n"
                         << extra;
  }

  TinyDesign::Outcome TinyDesign::run(const std::string &command, const unsigned int ranks) const
  {
    const std::string log = dir.file("log.txt");
    const std::string mpi =
      ranks > 1 ? std::string(MPIEXEC_EXECUTABLE) + " -np " + std::to_string(ranks) + " " : "";
    const int status = std::system((mpi + SOFTCHAIN_EXECUTABLE + " " + command +
                                    " " + prm() + " > " + log + " 2>&1")
                                     .c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(log)};
  }

  std::string TinyDesign::sweep_killed_after(const int lines, const int signal,
                                            int *const exit_status) const
  {
    int pipe_ends[2];
    if (::pipe(pipe_ends) != 0)
      return "";
    const pid_t child = ::fork();
    if (child == 0)
      {
        ::dup2(pipe_ends[1], STDOUT_FILENO);
        ::close(pipe_ends[0]);
        ::execl(SOFTCHAIN_EXECUTABLE, SOFTCHAIN_EXECUTABLE, "sweep", prm().c_str(), nullptr);
        ::_exit(127);
      }
    ::close(pipe_ends[1]);
    std::string output, line;
    char        c;
    int         solved = 0;
    while (solved < lines && ::read(pipe_ends[0], &c, 1) == 1)
      {
        output += c;
        if (c != '\n')
          continue;
        const auto start = output.rfind('\n', output.size() - 2);
        line = output.substr(start == std::string::npos ? 0 : start + 1);
        if (line.find("load steps") != std::string::npos)
          ++solved;
      }
    ::kill(child, signal);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (exit_status)
      *exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    ::close(pipe_ends[0]);
    return output;
  }

  std::string pipeline_samples()
  {
    return "set Pressure sweep = 1e3, 2e3, 3e3\n"
           "set Lateral tip forces = 0.005, 0.01\n"
           "set Torsion couples = 0.005, 0.01\n"
           "set Validation samples = 2e3 : tip : 0,0,0.005";
  }

  std::string pipeline_settings(const bool plots, const std::string &more)
  {
    return "subsection Springs\n  set Generate for bender = true\n"
           "  set Axial rigidity = fabric: 2000, thread: 500\nend\n"
           "subsection Reduction\n  set Joint spacing = 0.02\n"
           "  set Slab half-widths = 1\n  set Rotation threshold = 1e-6\n"
           "  set Plots = " + std::string(plots ? "true" : "false") + "\nend\n"
           "subsection Chain\n  set Slab half-width = 1\nend\n" + more;
  }

  TinyDesign pipeline_design(const std::string &name, const bool plots, const std::string &more)
  {
    return TinyDesign(name, pipeline_samples(), pipeline_settings(plots, more));
  }

  std::string sample_difference(const data::ActuationDatabase &a, const data::ActuationDatabase &b)
  {
    if (a.sample_ids() != b.sample_ids())
      return "the sample ids differ";
    for (const auto &id : a.sample_ids())
      {
        const std::string difference = record_difference(a.read_sample(id), b.read_sample(id));
        if (!difference.empty())
          return difference;
      }
    return "";
  }
} // namespace softchain::testing
