// ActuationDatabase under crashes and concurrent writers: a writer killed
// (SIGKILL) in the middle of storing sample k leaves exactly samples
// 0..k-1, bit for bit, and a rerun resumes; many interrupted writers in turn
// build the whole database; a second writer is refused while one has it
// open. The kills are deterministic: the child process sets the data
// layer's test hook SOFTCHAIN_TEST_KILL_IN_STORE (actuation_database.h).
#include <softchain/data/actuation_database.h>
#include <softchain/data/input_error.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "check_equal_samples.h"
#include "scratch_directory.h"

using namespace softchain::data;
using softchain::testing::check_equal_samples;
using softchain::testing::ScratchDirectory;

namespace
{
  const std::string hash = "crash";

  DesignRecord design()
  {
    return {"column", hash, "Q1", "test", "subsection Geometry\nend\n"};
  }

  // A column of 50 nodes read as six hexahedra: big enough for a sample
  // file of several HDF5 chunks of metadata and data, small enough to be fast.
  MeshRecord column_mesh()
  {
    MeshRecord mesh;
    for (int i = 0; i < 50; ++i)
      mesh.X.push_back({double(i % 2), double((i / 2) % 2), double(i / 4)});
    mesh.cavity_triangles = {{0, 1, 3}};
    mesh.tip_nodes        = {48, 49};
    mesh.base_nodes       = {0, 1, 2, 3};
    mesh.nodes_per_cell   = 8;
    for (int k = 0; k < 48; ++k)
      mesh.cells.push_back(k);
    return mesh;
  }

  // Sample k, with positions that are not round numbers, so that a torn or
  // mixed-up write cannot pass the bitwise comparison by chance.
  SampleRecord sample(int k)
  {
    SampleRecord s;
    s.actuation.pressure     = 1e3 * (k + 1) / 3.0;
    s.actuation.role         = k % 2 ? "pressure" : "lateral";
    s.actuation.point_forces = {{{1.0, 0.5, 12.0}, {0.0, -0.01 * k, 0.0}}};
    s.id                     = sample_id(hash, s.actuation);
    s.newton_iterations      = k;
    s.load_steps             = 1 + k % 3;
    s.wall_time              = 0.1 * k;
    for (const auto &X : column_mesh().X)
      s.x.push_back({X[0] + k / 7.0, X[1] - k / 11.0, X[2] * (1 + k / 13.0)});
    s.force_points_deformed = {{1.0 + k / 7.0, 0.5, 12.0}};
    s.base_force            = {0.0, -0.01 * k, 0.0};
    s.base_moment           = {0.12 * k, 0.0, -0.01 * k * (1.0 + k / 7.0)};
    return s;
  }

  // What a sweep does: stores the samples 0..n-1 not yet in the database.
  void store_missing(const std::string &path, int n)
  {
    auto database = ActuationDatabase::open_or_create(path, design(), column_mesh());
    for (int k = 0; k < n; ++k)
      if (!database.has_sample(sample(k).id))
        database.store_sample(sample(k));
  }

  // Runs store_missing(path, n) in a child process that the test hook kills
  // while it stores sample k (into a database of k samples); returns the
  // child's wait status.
  int writer_killed_in_store(const std::string &path, int n, int k)
  {
    const pid_t child = ::fork();
    if (child == 0)
      {
        ::setenv("SOFTCHAIN_TEST_KILL_IN_STORE", std::to_string(k).c_str(), 1);
        try
          {
            store_missing(path, n);
          }
        catch (...)
          {
            ::_exit(2);
          }
        ::_exit(0); // not killed: the test hook did not fire
      }
    int status = 0;
    ::waitpid(child, &status, 0);
    return status;
  }

  bool killed(int status)
  {
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
  }

  std::vector<std::string> ids_of(int first, int end)
  {
    std::vector<std::string> ids;
    for (int k = first; k < end; ++k)
      ids.push_back(sample(k).id);
    std::sort(ids.begin(), ids.end());
    return ids;
  }

  void check_all_samples(const std::string &path, int n)
  {
    const auto database = ActuationDatabase::open(path);
    REQUIRE(database.sample_ids() == ids_of(0, n));
    for (int k = 0; k < n; ++k)
      check_equal_samples(database.read_sample(sample(k).id), sample(k));
  }
} // namespace

TEST_CASE("a writer killed inside the store of sample k leaves samples 0..k-1, a rerun resumes")
{
  ScratchDirectory  dir("db_kill_in_store");
  const std::string path = dir.file("finger.h5");
  const int         n = 30, k = 17;
  REQUIRE(killed(writer_killed_in_store(path, n, k)));

  // The kill came inside the store: its temporary sample file is left over.
  std::size_t temporaries = 0;
  for (const auto &entry : std::filesystem::directory_iterator(path + ".samples"))
    temporaries += entry.path().extension() != ".h5";
  CHECK(temporaries == 1);

  check_all_samples(path, k);

  store_missing(path, n); // the rerun
  check_all_samples(path, n);
  // The rerun removed the temporary: only the n sample files remain.
  CHECK(std::distance(std::filesystem::directory_iterator(path + ".samples"),
                      std::filesystem::directory_iterator()) == n);
}

TEST_CASE("a database built by several interrupted writers reads back fully")
{
  ScratchDirectory  dir("db_interrupted_writers");
  const std::string path = dir.file("finger.h5");
  const int         n = 40, stores_per_writer = 7;
  // Each writer completes 7 stores and is killed in its 8th.
  for (int writer = 0; (writer + 1) * stores_per_writer < n; ++writer)
    {
      REQUIRE(killed(writer_killed_in_store(path, n, (writer + 1) * stores_per_writer)));
      CHECK(ActuationDatabase::open(path).sample_ids() ==
            ids_of(0, (writer + 1) * stores_per_writer));
    }
  store_missing(path, n);
  check_all_samples(path, n);
}

TEST_CASE("a second writer gets an error naming the database, readers are let in")
{
  ScratchDirectory  dir("db_second_writer");
  const std::string path = dir.file("finger.h5");
  // flock locks belong to an open file, so a second writer in this process
  // is refused just like one in another process.
  auto first = ActuationDatabase::open_or_create(path, design(), column_mesh());
  first.store_sample(sample(0));
  try
    {
      ActuationDatabase::open_or_create(path, design(), column_mesh());
      FAIL("a second writer was let in");
    }
  catch (const InputError &e)
    {
      CHECK_THAT(e.what(), Catch::Contains(path) && Catch::Contains("another writer"));
    }
  auto reader = ActuationDatabase::open(path);
  check_equal_samples(reader.read_sample(sample(0).id), sample(0));
  CHECK_THROWS_AS(reader.store_sample(sample(1)), InputError); // storing makes it a writer

  // Another process is refused as well, and gets in once the first lets go.
  CHECK(WEXITSTATUS(writer_killed_in_store(path, 3, 99)) == 2);
  first = ActuationDatabase::open(path); // drops the writer's lock
  CHECK(WEXITSTATUS(writer_killed_in_store(path, 3, 99)) == 0);
  check_all_samples(path, 3);
}
