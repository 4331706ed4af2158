// `softchain run FILE.prm`: the whole pipeline of the paper's Fig. 2 --
// FEM sample sweep -> reduction (stiffness CSVs) -> chain validation, MJCF
// export and MuJoCo's contact scenes -- and
// the report of it all (report.html, with the stages' wall times), with one
// progress line per stage and its wall time, then every output file with
// what it is. The sweep runs on all MPI ranks, the deal.II-free tiers on
// rank 0.
#include <softchain/chain/chain_run.h>
#include <softchain/chain/simulate_run.h>
#include <softchain/app/commands.h>
#include <softchain/data/input_error.h>
#include <softchain/data/output_files.h>
#include <softchain/reduction/reduction_run.h>
#include <softchain/report/report_run.h>
#include <softchain/fem/sample_sweep.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace softchain::app
{
  using namespace dealii;
  using namespace softchain::fem;

  namespace
  {
    namespace fs = std::filesystem;

    constexpr int n_stages = 4;

    // Runs one stage between two progress lines, appends its wall time to
    // `times` (for the report); returns its exit status.
    int stage(std::ostream &out, const int k, const std::string &name,
              std::vector<report::StageTime> &times, const std::function<int()> &body)
    {
      out << "== stage " << k << "/" << n_stages << ": " << name << std::endl;
      const auto   start   = std::chrono::steady_clock::now();
      const int    status  = body();
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      times.push_back({name, seconds});
      out << "== stage " << k << "/" << n_stages << ": " << name
          << (status == 0 ? " done" : " done with failures") << " in " << std::fixed
          << std::setprecision(2) << seconds << " s" << std::defaultfloat << std::endl;
      return status;
    }

    bool ends_with(const std::string &text, const std::string &suffix)
    {
      return text.size() >= suffix.size() &&
             text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
    }

    // What an output file is, from its place and name.
    std::string describe(const fs::path &file)
    {
      const std::string dir = file.parent_path().filename(), name = file.filename(),
                        ext = file.extension();
      if (name == "report.html")
        return "the report: design, deformed finger, stiffness, validation, tip-motion protocol, run times, paper's claims (open in a browser)";
      if (name == "database.h5")
        return "actuation-deformation database (HDF5): the design and the mesh";
      if (dir == "database.h5.samples")
        return "one sample of the database (HDF5): its load and deformed nodes";
      if (ends_with(dir, ".stale.samples"))
        return "one sample of an earlier design's database, moved aside";
      if (name == "protocol_samples.csv")
        return "the validation protocol's samples (inflated state, tip motions)";
      if (name == "database.h5.lock")
        return "the database's writer lock (empty)";
      if (ext == ".stale")
        return "database of an earlier design, moved aside";
      if (ext == ".gp")
        return "gnuplot script of the plot beside it";
      if (dir == "vtu")
        return name == "samples.pvd" ? "ParaView series of all samples (open this one)" :
               name.find("_springs") != std::string::npos ? "spring network of one sample (ParaView)" :
               ext == ".pvd" ? "ParaView series of one sample" : "deformed finger of one sample (ParaView)";
      if (dir == "stiffness")
        return ext == ".png" ? "stiffness plot" :
               name.find("_samples.csv") != std::string::npos ? "joint angles and torques per sample" :
               name.find("_kphi_vs_pressure") != std::string::npos ? "k_phi per pressure and joint" :
               name.find("_ktheta_vs_pressure") != std::string::npos ? "k_theta per pressure and joint" :
               name.find("_kpsi_vs_pressure") != std::string::npos ? "k_psi per pressure and joint" :
               name.find("_joint_law") != std::string::npos ? "the joints' torque-angle curves under forces" :
               name.find("_pressure_torque") != std::string::npos ? "pressure torque J_p per joint" :
               name.find("_link_geometry") != std::string::npos ? "the chain's joints and tip per pressure" :
               name.find("_link_shift") != std::string::npos ? "the links' shift per in-plane turn, per pressure" :
               name.find("_link_compliance") != std::string::npos ? "the links' compliance per pressure" :
               name.find("_skin_compliance") != std::string::npos ? "the sections' compliance under contact per pressure" :
               name.find("_skin_shear_compliance") != std::string::npos ? "the sections' shear compliance under friction per pressure" :
               ext == ".csv" ? "joint stiffness table k_psi, k_theta, k_phi" : "reduction output";
      if (dir == "chain")
        return name == "validation.csv" ? "chain vs FEM tip pose per sample and model" :
               name == "validation_summary.csv" ? "tip errors per model and role" :
               name == "fem_tip_poses.csv" ? "FEM tip position and bending angle per sample" :
               name == "protocol_torques.csv" ? "base torques over the tip-motion protocol, FEM and chains" :
               name == "protocol_summary.csv" ? "base torque errors of the protocol per model" :
               name == "grasp_summary.csv" ? "blocked-force and grasp errors of the chains in contact, per model" :
               name == "protocol_torques.png" ? "plot of the protocol's base torques" :
               ext == ".xml" ? "MuJoCo (MJCF) model of the chain" :
               ext == ".png" ? "validation plot" : "chain validation output";
      if (dir == data::folder::contact)
        return "force and moment on each obstacle per contact sample, and the tip pose";
      return "output";
    }

    // Every file under `directory`; the per-sample files (in vtu/ and the
    // database's sample directory) one line per kind with their count.
    void list_outputs(const std::string &directory)
    {
      std::vector<fs::path> files;
      for (const auto &entry : fs::recursive_directory_iterator(directory))
        if (entry.is_regular_file())
          files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      const auto per_sample = [](const fs::path &f) {
        const std::string dir = f.parent_path().filename();
        return (dir == "vtu" && f.filename() != "samples.pvd") || ends_with(dir, ".samples");
      };
      std::map<std::string, int> count;
      for (const auto &f : files)
        if (per_sample(f))
          ++count[describe(f)];
      std::set<std::string> shown;
      std::cout << "outputs:\n";
      for (const auto &f : files)
        {
          const std::string what = describe(f);
          if (per_sample(f) && !shown.insert(what).second)
            continue;
          std::cout << "  " << f.string() << "  " << what
                    << (per_sample(f) ? " (1 of " + std::to_string(count[what]) + ")" : "") << '\n';
        }
    }
  } // namespace

  int run_command(const data::PrmFile &prm_file)
  {
    const bool    root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    std::ostream  silent(nullptr);
    std::ostream &out = root ? std::cout : silent;
    std::string   database;
    std::vector<report::StageTime> times;
    const int     swept = stage(out, 1, "FEM sample sweep", times, [&] {
      const auto summary = SampleSweep(prm_file).run();
      database           = summary.database;
      return summary.report(out, root ? std::cerr : silent);
    });
    if (!root)
      return swept;
    const std::string directory = fs::path(database).parent_path().string();
    stage(out, 2, "reduction", times,
          [&] { return reduction::run_reduction(prm_file, database, directory); });
    const int chained = stage(out, 3, "chain validation", times, [&] {
      try
        {
          // The chain, its MuJoCo model, and MuJoCo in the contact
          // samples' scenes (the mujoco row of chain/grasp_summary.csv).
          const int status = chain::run_chain(prm_file, database, directory, true);
          chain::simulate_contact_scenes(prm_file, database, directory);
          return status;
        }
      catch (const data::InputError &e) // e.g. no usable stiffness: still write the report
        {
          std::cerr << "softchain: chain validation: " << e.what() << '\n';
          return 1;
        }
    });
    // The report's own time cannot be in the report: it lists stages 1-3.
    stage(out, 4, "report", times,
          [&] { return report::run_report(prm_file, database, directory, times); });
    list_outputs(directory);
    return std::max(swept, chained);
  }
} // namespace softchain::app
