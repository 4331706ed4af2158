// database_scale NODES SAMPLES: the cost of storing one sample as the
// database grows. Stores SAMPLES synthetic samples of a NODES-node mesh
// through ActuationDatabase::store_sample into a scratch database in the
// current directory (so that the disk measured is the one the user picks),
// times every store and prints the first and last ten store times (median
// and mean), the total, the size on disk and, as the last line,
//   store time ratio last/first: R
// (median of the last ten over median of the first ten). A store whose cost
// does not grow with the number of samples already stored has R near 1.
#include <softchain/data/actuation_database.h>
#include <softchain/data/statistics.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
  namespace fs   = std::filesystem;
  namespace data = softchain::data;
  using data::median;

  // A synthetic mesh: NODES points on a grid, read as hexahedra of eight
  // consecutive nodes. The data layer checks index ranges only, so any
  // node numbering will do for timing.
  data::MeshRecord synthetic_mesh(std::size_t n_nodes)
  {
    data::MeshRecord mesh;
    for (std::size_t i = 0; i < n_nodes; ++i)
      mesh.X.push_back({double(i % 2), double((i / 2) % 2), double(i / 4)});
    mesh.cavity_triangles = {{0, 1, 3}};
    mesh.tip_nodes        = {std::int64_t(n_nodes) - 1};
    mesh.base_nodes       = {0};
    mesh.nodes_per_cell   = 8;
    mesh.cells.resize(n_nodes / 8 * 8);
    std::iota(mesh.cells.begin(), mesh.cells.end(), 0);
    return mesh;
  }

  // Sample k: pressure (k + 1) kPa, every node moved by a k-dependent shift.
  data::SampleRecord synthetic_sample(const std::string &hash, const data::MeshRecord &mesh,
                                      std::size_t k)
  {
    data::SampleRecord sample;
    sample.actuation.pressure = 1e3 * double(k + 1);
    sample.actuation.role     = "pressure";
    sample.id                 = data::sample_id(hash, sample.actuation);
    sample.newton_iterations  = 5;
    sample.load_steps         = 1;
    const double shift        = 1e-3 * double(k + 1);
    for (const auto &X : mesh.X)
      sample.x.push_back({X[0] + shift, X[1] - shift, X[2] + shift * X[2]});
    return sample;
  }

  double mean(const std::vector<double> &values)
  {
    return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
  }

  // Bytes of all regular files under `root` (the database and its samples).
  std::uintmax_t bytes_under(const fs::path &root)
  {
    std::uintmax_t bytes = 0;
    for (const auto &entry : fs::recursive_directory_iterator(root))
      if (entry.is_regular_file())
        bytes += entry.file_size();
    return bytes;
  }

  void print_row(const char *label, const std::vector<double> &seconds)
  {
    std::printf("%-18s %12.2f %12.2f\n", label, 1e3 * median(seconds), 1e3 * mean(seconds));
  }

  // Parses a positive count, or returns 0.
  std::size_t positive_count(const char *text)
  {
    try
      {
        std::size_t used  = 0;
        const long  value = std::stol(text, &used);
        return used == std::string(text).size() && value > 0 ? std::size_t(value) : 0;
      }
    catch (const std::exception &)
      {
        return 0;
      }
  }
} // namespace

int main(int argc, char **argv)
{
  const std::size_t n_nodes   = argc == 3 ? positive_count(argv[1]) : 0;
  const std::size_t n_samples = argc == 3 ? positive_count(argv[2]) : 0;
  if (n_nodes < 8 || n_samples == 0)
    {
      std::cerr << "usage: database_scale NODES SAMPLES (NODES >= 8, SAMPLES >= 1)\n";
      return 1;
    }
  const fs::path scratch = fs::absolute("database_scale." + std::to_string(::getpid()));
  try
    {
      fs::create_directories(scratch);
      const data::DesignRecord design{"synthetic", "database_scale", "Q1", "benchmark", ""};
      const data::MeshRecord   mesh = synthetic_mesh(n_nodes);
      auto database = data::ActuationDatabase::open_or_create((scratch / "database.h5").string(),
                                                              design, mesh);

      std::vector<double> seconds;
      for (std::size_t k = 0; k < n_samples; ++k)
        {
          const auto sample = synthetic_sample(design.design_hash, mesh, k);
          const auto start  = std::chrono::steady_clock::now();
          database.store_sample(sample);
          seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }

      const std::size_t         n_ends = std::min<std::size_t>(10, n_samples);
      const std::vector<double> first(seconds.begin(), seconds.begin() + n_ends);
      const std::vector<double> last(seconds.end() - n_ends, seconds.end());
      std::printf("database_scale: %zu nodes (%.2f MB of positions per sample), %zu samples\n",
                  n_nodes, 24e-6 * double(n_nodes), n_samples);
      std::printf("%-18s %12s %12s\n", "store time [ms]", "median", "mean");
      print_row("first 10 samples", first);
      print_row("last 10 samples", last);
      const double total = std::accumulate(seconds.begin(), seconds.end(), 0.0);
      std::printf("total store time: %.2f s (%.2f ms per sample)\n", total,
                  1e3 * total / double(n_samples));
      std::printf("size on disk: %.1f MB\n", 1e-6 * double(bytes_under(scratch)));
      std::printf("store time ratio last/first: %.2f\n", median(last) / median(first));
    }
  catch (const std::exception &e)
    {
      std::cerr << "database_scale: " << e.what() << '\n';
      fs::remove_all(scratch);
      return 1;
    }
  fs::remove_all(scratch);
  return 0;
}
