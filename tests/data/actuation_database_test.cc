// ActuationDatabase: round trip, replacement, cache, stale files, bad files,
// databases in the single-file layout of earlier versions.
#include <softchain/data/actuation_database.h>
#include <softchain/data/input_error.h>

#include <catch2/catch.hpp>

#include <hdf5.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>

#include "check_equal_samples.h"
#include "scratch_directory.h"

using namespace softchain::data;
using softchain::testing::check_equal_samples;
using softchain::testing::ScratchDirectory;

namespace
{
  DesignRecord design(const std::string &hash)
  {
    return {"cube", hash, "Q1", "test", "subsection Finger design\nend\n"};
  }

  // One hexahedron (unit cube) with a "cavity" made of two triangles.
  MeshRecord cube_mesh()
  {
    MeshRecord mesh;
    for (int k = 0; k < 8; ++k)
      mesh.X.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
    mesh.cavity_triangles = {{0, 1, 3}, {0, 3, 2}};
    mesh.tip_nodes        = {1, 3, 5, 7};
    mesh.base_nodes       = {0, 2, 4, 6};
    mesh.nodes_per_cell   = 8;
    for (int k = 0; k < 8; ++k)
      mesh.cells.push_back(k);
    return mesh;
  }

  SampleRecord sample(const std::string &hash, double pressure, double shift)
  {
    SampleRecord s;
    s.actuation.pressure     = pressure;
    s.actuation.role         = "pressure";
    s.actuation.point_forces = {{{1.0, 0.5, 0.5}, {0.0, -0.25, 0.0}}};
    s.id                     = sample_id(hash, s.actuation);
    s.newton_iterations      = 7;
    s.load_steps             = 3;
    s.wall_time              = 1.5;
    for (const auto &X : cube_mesh().X)
      s.x.push_back({X[0] + shift, X[1], X[2] - shift});
    s.force_points_deformed = {{1.0 + shift, 0.5, 0.5 - shift}};
    s.base_force            = {0.0, -0.25, 0.0};
    s.base_moment           = {0.0, 0.0, -0.25 * (1.0 + shift)};
    if (shift > 0) // a sample that buckled on the way, and others that did not
      s.force_limit = 0.2 + shift;
    return s;
  }

  template <typename F>
  void require_input_error_naming(const std::string &name, F &&f)
  {
    try
      {
        f();
        FAIL("no InputError thrown");
      }
    catch (const InputError &e)
      {
        CHECK_THAT(e.what(), Catch::Contains(name));
      }
  }
} // namespace

TEST_CASE("database round trip of design, mesh and samples")
{
  ScratchDirectory  dir("db_round_trip");
  const std::string path = dir.file("finger.h5");
  auto              db   = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  SampleRecord      failed = sample("h1", 2e4, 0.25);
  failed.status              = SampleStatus::failed;
  failed.reason              = "Newton did not converge";
  failed.load_factor_reached = 0.5;
  SampleRecord limit         = sample("h1", 8e4, 0.75);
  limit.status               = SampleStatus::limit_point;
  limit.reason               = "limit point at p = 80000 Pa";
  db.store_sample(sample("h1", 1e4, 0.125));
  db.store_sample(failed);
  db.store_sample(limit);

  const auto again = ActuationDatabase::open(path);
  CHECK(again.design().name == "cube");
  CHECK(again.design().design_hash == "h1");
  CHECK(again.design().parameters == design("h1").parameters);
  CHECK(again.mesh().X == cube_mesh().X);
  CHECK(again.mesh().cavity_triangles == cube_mesh().cavity_triangles);
  CHECK(again.mesh().tip_nodes == cube_mesh().tip_nodes);
  CHECK(again.mesh().base_nodes == cube_mesh().base_nodes);
  CHECK(again.mesh().cells == cube_mesh().cells);
  CHECK(again.mesh().nodes_per_cell == 8);
  REQUIRE(again.sample_ids().size() == 3);
  CHECK(again.read_sample(limit.id).status == SampleStatus::limit_point);
  CHECK(again.read_sample(failed.id).status == SampleStatus::failed);
  CHECK_FALSE(again.read_sample(failed.id).converged());
  check_equal_samples(again.read_sample(sample("h1", 1e4, 0.125).id), sample("h1", 1e4, 0.125));
  const SampleRecord read_failed = again.read_sample(failed.id);
  check_equal_samples(read_failed, failed);
  CHECK_FALSE(read_failed.converged());
  // Nothing but the database, its sample directory with one file per
  // sample and the lock file are left (no temporaries).
  std::set<std::string> names;
  for (const auto &entry : std::filesystem::directory_iterator(dir.path()))
    names.insert(entry.path().filename().string());
  CHECK(names == std::set<std::string>{"finger.h5", "finger.h5.samples", "finger.h5.lock"});
  CHECK(std::distance(std::filesystem::directory_iterator(path + ".samples"),
                      std::filesystem::directory_iterator()) == 3);
}

TEST_CASE("storing a sample with an existing id replaces it")
{
  ScratchDirectory dir("db_replace");
  auto db = ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh());
  db.store_sample(sample("h1", 1e4, 0.125));
  db.store_sample(sample("h1", 1e4, 0.5)); // same actuation, so same id
  const auto again = ActuationDatabase::open(dir.file("f.h5"));
  REQUIRE(again.sample_ids().size() == 1);
  check_equal_samples(again.read_sample(again.sample_ids()[0]), sample("h1", 1e4, 0.5));
}

TEST_CASE("the same design reuses the stored samples as a cache")
{
  ScratchDirectory dir("db_cache");
  ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh())
    .store_sample(sample("h1", 1e4, 0.125));
  const auto db = ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh());
  Actuation  same;
  same.pressure     = 1e4;
  same.role         = "another role"; // the role is not part of the key
  same.point_forces = sample("h1", 1e4, 0).actuation.point_forces;
  CHECK(db.has_sample(sample_id("h1", same)));
  same.pressure = 1e4 * (1 + 1e-15);
  CHECK_FALSE(db.has_sample(sample_id("h1", same)));
  CHECK(sample_id("h2", sample("h1", 1e4, 0).actuation) != sample("h1", 1e4, 0).id);
}

TEST_CASE("a new design hash moves the old database aside")
{
  ScratchDirectory dir("db_stale");
  ActuationDatabase::open_or_create(dir.file("f.h5"), design("old"), cube_mesh())
    .store_sample(sample("old", 1e4, 0.125));
  const auto db = ActuationDatabase::open_or_create(dir.file("f.h5"), design("new"), cube_mesh());
  CHECK(db.design().design_hash == "new");
  CHECK(db.sample_ids().empty());
  const auto stale = ActuationDatabase::open(dir.file("f.h5.old.stale"));
  CHECK(stale.design().design_hash == "old");
  REQUIRE(stale.sample_ids().size() == 1);
  check_equal_samples(stale.read_sample(stale.sample_ids()[0]), sample("old", 1e4, 0.125));
  // The old samples moved with their database file: none is left beside the new one.
  CHECK(std::filesystem::is_empty(dir.file("f.h5.samples")));
}

TEST_CASE("the plan hides samples the .prm no longer asks for, which stay stored as a cache")
{
  ScratchDirectory   dir("db_plan");
  const SampleRecord kept = sample("h1", 1e4, 0.125), dropped = sample("h1", 2e4, 0.25),
                     failed = sample("h1", 3e4, 0.5);
  std::vector<std::string> expected{kept.id, failed.id};
  std::sort(expected.begin(), expected.end());
  {
    auto db = ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh());
    for (const auto &s : {kept, dropped, failed})
      db.store_sample(s);
    // Without a plan (a database whose first sweep has not completed) the
    // readers see every stored sample.
    CHECK(ActuationDatabase::open(dir.file("f.h5")).sample_ids().size() == 3);

    // The plan lists one sample that was never stored (a sweep names every
    // sample it asked for): readers see the stored ones of the plan.
    const std::string never = sample_id("h1", sample("h1", 4e4, 0).actuation);
    db.set_plan({failed.id, kept.id, never, kept.id});
    for (const auto &reader : {db, ActuationDatabase::open(dir.file("f.h5"))})
      {
        CHECK(reader.sample_ids() == expected);
        CHECK(reader.stored_sample_ids().size() == 3);
        CHECK(reader.has_sample(dropped.id)); // still a cache hit for the sweep
        check_equal_samples(reader.read_sample(dropped.id), dropped);
      }

    // The same plan again rewrites nothing (a rerun of the same .prm).
    const auto written = std::filesystem::last_write_time(dir.file("f.h5.plan"));
    std::filesystem::last_write_time(dir.file("f.h5.plan"), written - std::chrono::hours(1));
    db.set_plan({kept.id, failed.id, never});
    CHECK(std::filesystem::last_write_time(dir.file("f.h5.plan")) == written - std::chrono::hours(1));
  } // the writer lets go of the database

  // A design change moves the plan aside with its samples.
  ActuationDatabase::open_or_create(dir.file("f.h5"), design("h2"), cube_mesh());
  CHECK_FALSE(std::filesystem::exists(dir.file("f.h5.plan")));
  CHECK(ActuationDatabase::open(dir.file("f.h5.h1.stale")).sample_ids() == expected);
}

TEST_CASE("a plan file with a line that is not a sample id is an InputError naming it")
{
  ScratchDirectory dir("db_bad_plan");
  ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh())
    .store_sample(sample("h1", 1e4, 0.125));
  std::ofstream(dir.file("f.h5.plan")) << "0123456789abcdef\n../escape\n";
  require_input_error_naming("f.h5.plan:2", [&] { ActuationDatabase::open(dir.file("f.h5")); });
}

TEST_CASE("a sample directory without its database file is an error, not reused")
{
  ScratchDirectory dir("db_orphan");
  ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh())
    .store_sample(sample("h1", 1e4, 0.125));
  std::filesystem::remove(dir.file("f.h5"));
  require_input_error_naming(dir.file("f.h5.samples"), [&] {
    ActuationDatabase::open_or_create(dir.file("f.h5"), design("h2"), cube_mesh());
  });
  CHECK(std::filesystem::exists(dir.file("f.h5.samples/") + sample("h1", 1e4, 0.125).id + ".h5"));
}

TEST_CASE("a sample file of another design is an InputError naming it")
{
  ScratchDirectory dir("db_foreign_sample");
  ActuationDatabase::open_or_create(dir.file("a.h5"), design("a"), cube_mesh())
    .store_sample(sample("a", 1e4, 0.125));
  auto b = ActuationDatabase::open_or_create(dir.file("b.h5"), design("b"), cube_mesh());
  const std::string id = sample("a", 1e4, 0.125).id;
  std::filesystem::copy_file(dir.file("a.h5.samples/") + id + ".h5",
                             dir.file("b.h5.samples/") + id + ".h5");
  require_input_error_naming(dir.file("b.h5.samples/") + id + ".h5",
                             [&] { ActuationDatabase::open(dir.file("b.h5")).read_sample(id); });
}

namespace
{
  // Turns a database into the single-file layout of earlier versions: each
  // sample file's root (attributes and datasets) is copied into the database
  // file as /samples/<id>, and the sample directory is removed.
  void convert_to_single_file(const std::string &path)
  {
    const hid_t file    = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t samples = H5Gcreate2(file, "samples", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (const auto &entry : std::filesystem::directory_iterator(path + ".samples"))
      {
        const hid_t sample = H5Fopen(entry.path().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        H5Ocopy(sample, ".", samples, entry.path().stem().c_str(), H5P_DEFAULT, H5P_DEFAULT);
        H5Fclose(sample);
      }
    H5Gclose(samples);
    H5Fclose(file);
    std::filesystem::remove_all(path + ".samples");
  }
} // namespace

TEST_CASE("a sample stored without a base wrench reads it as NaN")
{
  // Databases written before the base wrench was stored have no dataset.
  ScratchDirectory  dir("db_no_wrench");
  const std::string path = dir.file("f.h5");
  auto              db   = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  db.store_sample(sample("h1", 1e4, 0.125));
  const std::string file = path + ".samples/" + sample("h1", 1e4, 0.125).id + ".h5";
  const hid_t       h5   = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(H5Ldelete(h5, "base_wrench", H5P_DEFAULT) >= 0);
  H5Fclose(h5);
  const SampleRecord read = ActuationDatabase::open(path).read_sample(sample("h1", 1e4, 0.125).id);
  for (int c = 0; c < 3; ++c)
    CHECK((std::isnan(read.base_force[c]) && std::isnan(read.base_moment[c])));
  CHECK(read.x == sample("h1", 1e4, 0.125).x);
}

TEST_CASE("a prescribed tip motion is part of the sample's id and reads back")
{
  ScratchDirectory  dir("db_tip_motion");
  const std::string path  = dir.file("f.h5");
  auto              db    = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  const SampleRecord free = sample("h1", 1e4, 0.125);
  SampleRecord       held = free;
  held.actuation.role       = "protocol";
  held.actuation.tip_motion = TipMotion{{0.0, 0.0, 0.01}, {0.0, 0.0, 0.0}};
  held.id                   = sample_id("h1", held.actuation);
  // A moved tip is another sample; a zero motion still differs from a free
  // tip (the tip is held), and the free sample's text is the one it had
  // before tip motions existed.
  CHECK(held.id != free.id);
  SampleRecord zero         = held;
  zero.actuation.tip_motion = TipMotion{};
  CHECK(sample_id("h1", zero.actuation) != free.id);
  CHECK(free.actuation.canonical_text().find("tip motion") == std::string::npos);
  SampleRecord turned = held;
  turned.actuation.tip_motion->rotation = {0.1, 0.0, 0.0};
  CHECK(sample_id("h1", turned.actuation) != held.id);
  SampleRecord pointed = held; // the same translation by a point contact
  pointed.actuation.tip_motion->point_contact = true;
  pointed.id = sample_id("h1", pointed.actuation);
  CHECK(pointed.id != held.id);

  db.store_sample(free);
  db.store_sample(held);
  db.store_sample(pointed);
  const auto again = ActuationDatabase::open(path);
  check_equal_samples(again.read_sample(held.id), held);
  const auto motion = again.read_sample(held.id).actuation.tip_motion;
  REQUIRE(motion);
  CHECK(motion->translation == held.actuation.tip_motion->translation);
  CHECK(motion->rotation == held.actuation.tip_motion->rotation);
  CHECK_FALSE(motion->point_contact);
  CHECK(again.read_sample(pointed.id).actuation.tip_motion->point_contact);
  check_equal_samples(again.read_sample(pointed.id), pointed);
  CHECK_FALSE(again.read_sample(free.id).actuation.tip_motion);
}

TEST_CASE("a volume-controlled sample is identified by its volume ratio and keeps the pressure found")
{
  ScratchDirectory   dir("db_volume_ratio");
  const std::string  path     = dir.file("f.h5");
  auto               db       = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  const SampleRecord pressure = sample("h1", 1.7e4, 0.125);
  SampleRecord       inflated = pressure;
  inflated.actuation.role                = "volume";
  inflated.actuation.cavity_volume_ratio = 2.5;
  inflated.id                            = sample_id("h1", inflated.actuation);
  // The ratio, not the pressure (an outcome), names the sample: the same
  // pressure found at another ratio is another sample, another pressure
  // found at the same ratio the same one; a pressure sample's text is as before.
  CHECK(inflated.id != pressure.id);
  SampleRecord other_found = inflated;
  other_found.actuation.pressure = 1.2e4;
  CHECK(sample_id("h1", other_found.actuation) == inflated.id);
  SampleRecord other_ratio = inflated;
  other_ratio.actuation.cavity_volume_ratio = 3.0;
  CHECK(sample_id("h1", other_ratio.actuation) != inflated.id);
  CHECK(pressure.actuation.canonical_text().find("volume") == std::string::npos);

  db.store_sample(pressure);
  db.store_sample(inflated);
  const auto again = ActuationDatabase::open(path);
  const auto read  = again.read_sample(inflated.id);
  check_equal_samples(read, inflated);
  REQUIRE(read.actuation.cavity_volume_ratio);
  CHECK(*read.actuation.cavity_volume_ratio == 2.5);
  CHECK(read.actuation.pressure == 1.7e4);
  CHECK_FALSE(again.read_sample(pressure.id).actuation.cavity_volume_ratio);
}

TEST_CASE("a contact sample keeps its obstacles in order, their wrenches and its contact law")
{
  ScratchDirectory   dir("db_contact");
  const std::string  path = dir.file("f.h5");
  auto               db   = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  const SampleRecord free = sample("h1", 2e4, 0.125);
  SampleRecord       pressed = free;
  pressed.actuation.role = "contact";
  // Named against the alphabet, so that the stored order, not the HDF5
  // group's, must come back.
  ObstacleRecord table{"table", "plane", {0, -0.005, 0}, {0, 1, 0}, 0, {}, 0, {}};
  ObstacleRecord can{"can", "cylinder", {0.05, -0.015, 0}, {0, 0, 1}, 0.01, {}, 0.5, {0, 0.002, 0}};
  ObstacleRecord crate{"crate", "box", {0.05, -0.03, 0}, {}, 0, {0.01, 0.005, 0.02}, 0, {}, {0, 0, 0.3}};
  pressed.actuation.obstacles   = {table, can, crate};
  pressed.actuation.contact_law = "surfaces all penalty 10";
  pressed.obstacle_wrenches     = {{{0.1, -0.8, 0}, {0, 0, 0.07}}, {{0, -0.25, 0.01}, {0.001, 0, 0.02}}, {}};
  pressed.id                    = sample_id("h1", pressed.actuation);

  // The obstacles, each field of them and the contact law name the sample;
  // a free finger's text is the one it had before contact existed.
  CHECK(pressed.id != free.id);
  CHECK(free.actuation.canonical_text().find("contact") == std::string::npos);
  // An unturned obstacle's text is the one it had before boxes could turn.
  CHECK(table.canonical_text().find("rotation") == std::string::npos);
  for (const auto change : {+[](Actuation &a) { a.obstacles[1].radius = 0.011; },
                            +[](Actuation &a) { a.obstacles[1].friction = 0.4; },
                            +[](Actuation &a) { a.obstacles[0].position[1] = -0.004; },
                            +[](Actuation &a) { a.obstacles[1].motion[1] = 0.003; },
                            +[](Actuation &a) { a.obstacles[2].rotation[2] = 0.4; },
                            +[](Actuation &a) { std::swap(a.obstacles[0], a.obstacles[1]); },
                            +[](Actuation &a) { a.contact_law += " tolerance 0.02"; }})
    {
      Actuation other = pressed.actuation;
      change(other);
      CHECK(sample_id("h1", other) != pressed.id);
    }

  db.store_sample(free);
  db.store_sample(pressed);
  const auto again = ActuationDatabase::open(path);
  const auto read  = again.read_sample(pressed.id);
  check_equal_samples(read, pressed);
  REQUIRE(read.actuation.obstacles.size() == 3);
  CHECK(read.actuation.obstacles[0].name == "table");
  CHECK(read.actuation.obstacles[1].shape == "cylinder");
  CHECK(read.actuation.obstacles[1].friction == 0.5);
  CHECK(read.actuation.obstacles[2].rotation == crate.rotation);
  CHECK(read.actuation.contact_law == pressed.actuation.contact_law);
  CHECK(again.read_sample(free.id).actuation.obstacles.empty());
  CHECK(again.read_sample(free.id).obstacle_wrenches.empty());
}

TEST_CASE("a meshed obstacle and a turning one come back from a contact sample, and name it")
{
  ScratchDirectory  dir("db_contact_stl");
  const std::string path = dir.file("f.h5");
  auto              db   = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  SampleRecord      pressed = sample("h1", 2e4, 0.125);
  pressed.actuation.role    = "contact";
  // A tetrahedron from an STL file, and a plane turning about a pivot.
  ObstacleRecord stone{"stone", "stl", {0.05, -0.02, 0}, {}, 0, {}, 0.2, {0, 0.001, 0}, {0.1, 0, 0}};
  stone.vertices = {{0, 0, 0}, {0, 0.01, 0}, {0.01, 0, 0}, {0, 0, 0}, {0.01, 0, 0}, {0, 0, 0.01},
                    {0, 0, 0}, {0, 0, 0.01}, {0, 0.01, 0}, {0.01, 0, 0}, {0, 0.01, 0}, {0, 0, 0.01}};
  stone.file = "stone.stl";
  ObstacleRecord table{"table", "plane", {0, -0.005, 0}, {0, 1, 0}, 0, {}, 0, {0, 0.002, 0}};
  table.motion_rotation = {0, 0, 0.2};
  table.motion_pivot    = {0.01, -0.005, 0};
  pressed.actuation.obstacles   = {stone, table};
  pressed.actuation.contact_law = "surfaces all penalty 10";
  pressed.obstacle_wrenches     = {{{0.1, -0.8, 0}, {0, 0, 0.07}}, {{0, -0.25, 0.01}, {0.001, 0, 0.02}}};
  pressed.id                    = sample_id("h1", pressed.actuation);

  // The obstacles' texts without a turn or triangles are those of before;
  // the triangles' content, the turn and its pivot name the sample, the
  // file's name does not.
  ObstacleRecord still = table;
  still.motion_rotation = {};
  CHECK(still.canonical_text() == "obstacle table plane 0 -0.0050000000000000001 0 0 1 0 0 0 0 0 0.002 0 0 0\n");
  for (const auto change : {+[](Actuation &a) { a.obstacles[0].vertices[1][1] = 0.011; },
                            +[](Actuation &a) { std::swap(a.obstacles[0].vertices[0], a.obstacles[0].vertices[1]); },
                            +[](Actuation &a) { a.obstacles[1].motion_rotation[2] = 0.21; },
                            +[](Actuation &a) { a.obstacles[1].motion_pivot[0] = 0.02; }})
    {
      Actuation other = pressed.actuation;
      change(other);
      CHECK(sample_id("h1", other) != pressed.id);
    }
  Actuation moved_file = pressed.actuation;
  moved_file.obstacles[0].file = "elsewhere/stone.stl";
  CHECK(sample_id("h1", moved_file) == pressed.id);

  db.store_sample(pressed);
  const auto read = ActuationDatabase::open(path).read_sample(pressed.id);
  check_equal_samples(read, pressed);
  REQUIRE(read.actuation.obstacles.size() == 2);
  CHECK(read.actuation.obstacles[0].vertices == stone.vertices);
  CHECK(read.actuation.obstacles[0].file == stone.file);
  CHECK(read.actuation.obstacles[0].rotation == stone.rotation);
  CHECK(read.actuation.obstacles[1].motion_rotation == table.motion_rotation);
  CHECK(read.actuation.obstacles[1].motion_pivot == table.motion_pivot);
  CHECK(read.actuation.obstacles[1].vertices.empty());
  CHECK(sample_id("h1", read.actuation) == pressed.id);
}

TEST_CASE("a database in the single-file layout of earlier versions opens and extends")
{
  ScratchDirectory  dir("db_single_file");
  const std::string path = dir.file("f.h5");
  {
    auto db = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
    db.store_sample(sample("h1", 1e4, 0.125));
    db.store_sample(sample("h1", 2e4, 0.25));
  }
  convert_to_single_file(path);
  REQUIRE_FALSE(std::filesystem::exists(path + ".samples"));

  const auto old = ActuationDatabase::open(path);
  REQUIRE(old.sample_ids().size() == 2);
  check_equal_samples(old.read_sample(sample("h1", 1e4, 0.125).id), sample("h1", 1e4, 0.125));
  check_equal_samples(old.read_sample(sample("h1", 2e4, 0.25).id), sample("h1", 2e4, 0.25));

  // A sweep of the same design keeps it, adds samples and replaces one
  // (the sample file takes precedence over the copy inside the file).
  auto db = ActuationDatabase::open_or_create(path, design("h1"), cube_mesh());
  db.store_sample(sample("h1", 3e4, 0.375));
  db.store_sample(sample("h1", 2e4, 0.5)); // the id of 2e4
  const auto again = ActuationDatabase::open(path);
  REQUIRE(again.sample_ids().size() == 3);
  check_equal_samples(again.read_sample(sample("h1", 1e4, 0.125).id), sample("h1", 1e4, 0.125));
  check_equal_samples(again.read_sample(sample("h1", 2e4, 0.5).id), sample("h1", 2e4, 0.5));
  check_equal_samples(again.read_sample(sample("h1", 3e4, 0.375).id), sample("h1", 3e4, 0.375));
}

TEST_CASE("missing and non-database files give an InputError naming the file")
{
  ScratchDirectory dir("db_bad");
  require_input_error_naming(dir.file("none.h5"),
                             [&] { ActuationDatabase::open(dir.file("none.h5")); });
  std::ofstream(dir.file("text.h5")) << "not HDF5\n";
  require_input_error_naming(dir.file("text.h5"),
                             [&] { ActuationDatabase::open(dir.file("text.h5")); });
  require_input_error_naming(dir.file("text.h5"), [&] {
    ActuationDatabase::open_or_create(dir.file("text.h5"), design("h"), cube_mesh());
  });
  const auto db = ActuationDatabase::open_or_create(dir.file("f.h5"), design("h1"), cube_mesh());
  require_input_error_naming("no sample 'nope'", [&] { db.read_sample("nope"); });
}
