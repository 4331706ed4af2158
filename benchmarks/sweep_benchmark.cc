// Sweep benchmark: the paper's extraction set for one design -- 8
// pressures 10..80 kPa, 10 lateral tip forces and 10 torsion couples
// 0.1..1 N at p = 0 (28 samples) -- swept three times by the softchain
// executable: with continuation, without (every sample from rest), and a
// fully cached rerun. Prints a table of wall time, load steps, Newton
// iterations and converged samples.
//
// usage: sweep_benchmark [BASE.prm [Subsection/Entry=Value ...]]
//   default BASE.prm: parameter_files/demo_bender.prm; the overrides change
//   the base design, e.g. "Mesh/Element type=Q1".
#include <softchain/data/actuation_database.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  const char *extraction_set = "subsection Samples\n"
                               "  set Pressure sweep = 10e3, 20e3, 30e3, 40e3, 50e3, 60e3, 70e3, 80e3\n"
                               "  set Lateral tip forces = 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1\n"
                               "  set Torsion couples = 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1\n";

  struct Row
  {
    std::string name;
    double      wall_time = 0;
    int         load_steps = 0, newton_iterations = 0, converged = 0, samples = 0;
  };

  // "Subsection/Entry=Value" as .prm text.
  std::string override_text(const std::string &setting)
  {
    const auto slash = setting.find('/'), equal = setting.find('=');
    if (slash == std::string::npos || equal == std::string::npos || equal < slash)
      throw std::invalid_argument("override '" + setting + "' is not Subsection/Entry=Value");
    return "subsection " + setting.substr(0, slash) + "\n  set " +
           setting.substr(slash + 1, equal - slash - 1) + " = " + setting.substr(equal + 1) +
           "\nend\n";
  }

  // The base design with the extraction set, writing into `output`.
  void write_prm(const std::string &file, const std::string &base_text,
                 const std::string &overrides, const std::string &output, bool continuation)
  {
    std::ofstream(file) << base_text << overrides << "subsection Design\n  set Output directory = "
                        << output << "\nend\nsubsection Output\n  set Write VTU = false\n"
                        << "  set Verbose = false\nend\n"
                        << extraction_set << "  set Continuation = "
                        << (continuation ? "true" : "false") << "\nend\n";
  }

  Row sweep(const std::string &name, const std::string &prm, const std::string &database)
  {
    const auto start = std::chrono::steady_clock::now();
    const int  status =
      std::system((std::string(SOFTCHAIN_EXECUTABLE) + " sweep " + prm + " > " + prm + ".log 2>&1").c_str());
    Row row{name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    if (status != 0)
      std::cerr << name << ": softchain sweep exited with " << status << " (see " << prm << ".log)\n";
    const auto db = softchain::data::ActuationDatabase::open(database);
    for (const auto &id : db.sample_ids())
      {
        const auto s = db.read_sample(id);
        row.load_steps += s.load_steps;
        row.newton_iterations += s.newton_iterations;
        row.converged += s.converged();
        ++row.samples;
      }
    return row;
  }

  void print(const std::vector<Row> &rows)
  {
    std::printf("| sweep | wall time [s] | load steps | Newton iterations | converged |\n"
                "| --- | ---: | ---: | ---: | ---: |\n");
    for (const auto &r : rows)
      std::printf("| %s | %.2f | %d | %d | %d/%d |\n", r.name.c_str(), r.wall_time, r.load_steps,
                  r.newton_iterations, r.converged, r.samples);
    std::printf("\ncontinuation saves %.0f%% of the wall time (%.2fx faster); cached rerun %.2f s\n",
                100 * (1 - rows[0].wall_time / rows[1].wall_time),
                rows[1].wall_time / rows[0].wall_time, rows[2].wall_time);
  }
} // namespace

int main(int argc, char **argv)
{
  const std::string base = argc > 1 ? argv[1] : SOFTCHAIN_SOURCE_DIR "/parameter_files/demo_bender.prm";
  std::string       overrides;
  for (int k = 2; k < argc; ++k)
    overrides += override_text(argv[k]);
  std::ostringstream base_text;
  base_text << std::ifstream(base).rdbuf();
  const fs::path dir = fs::temp_directory_path() / "softchain_sweep_benchmark";
  fs::remove_all(dir);
  fs::create_directories(dir);

  std::vector<Row> rows;
  for (const bool continuation : {true, false})
    {
      const std::string name = continuation ? "continuation" : "from rest";
      const std::string out  = (dir / (continuation ? "continued" : "rest")).string();
      const std::string prm  = (dir / (name.substr(0, 4) + ".prm")).string();
      write_prm(prm, base_text.str(), overrides, out, continuation);
      rows.push_back(sweep(name, prm, out + "/database.h5"));
    }
  rows.push_back(sweep("cached rerun", (dir / "cont.prm").string(), (dir / "continued/database.h5").string()));
  std::printf("%s%s: %d samples, 2 cores\n\n", base.c_str(), overrides.empty() ? "" : " (with overrides)",
              rows[0].samples);
  print(rows);
}
