// The mesh cache: an unchanged design is meshed once; a change of a mesh
// parameter meshes again; a change of a spring parameter does not.
#include <softchain/data/input_error.h>
#include <softchain/geometry/generate_design.h>

#include <catch2/catch.hpp>

#include <filesystem>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;
using Catch::Matchers::Contains;

TEST_CASE("an unchanged design is not meshed twice", "[geometry][cache]")
{
  const std::string dir = scratch_directory("cache_reuse");
  const std::string prm = design_variant("p10", dir, {{"Resolution", "0"}});
  GmshMesher        mesher(dir + "/cache");

  const GeneratedDesign first = generate_design(FingerDesign::read(prm), mesher);
  CHECK(mesher.n_runs() == 1);
  const auto written = std::filesystem::last_write_time(first.mesh_file);

  const GeneratedDesign second = generate_design(FingerDesign::read(prm), mesher);
  CHECK(mesher.n_runs() == 1);
  CHECK(second.mesh_file == first.mesh_file);
  CHECK(second.hash == first.hash);
  CHECK(std::filesystem::last_write_time(second.mesh_file) == written);

  // The cache lives on disk: a new mesher (a new process) finds it too.
  GmshMesher later(dir + "/cache");
  CHECK(generate_design(FingerDesign::read(prm), later).mesh_file == first.mesh_file);
  CHECK(later.n_runs() == 0);
}

TEST_CASE("a changed mesh parameter meshes again, a changed spring parameter does not",
          "[geometry][cache]")
{
  const std::string dir = scratch_directory("cache_keys");
  GmshMesher        mesher(dir + "/cache");
  const auto        generate = [&](const std::vector<std::pair<std::string, std::string>> &changes) {
    auto all = changes;
    all.emplace_back("Resolution", "0");
    return generate_design(FingerDesign::read(design_variant("p10", dir, all)), mesher);
  };
  const GeneratedDesign original = generate({});
  const GeneratedDesign thicker  = generate({{"Wall thickness", "0.003"}});
  CHECK(mesher.n_runs() == 2);
  CHECK(thicker.mesh_file != original.mesh_file);
  CHECK(thicker.hash != original.hash);

  const GeneratedDesign denser_threads = generate({{"Thread pitch", "0.004"}});
  CHECK(mesher.n_runs() == 2);
  CHECK(denser_threads.mesh_file == original.mesh_file);
  CHECK(denser_threads.hash != original.hash);
  CHECK(denser_threads.spring_file != original.spring_file);
}

TEST_CASE("a failing gmsh run is an input error and caches nothing", "[geometry][cache][errors]")
{
  const std::string dir = scratch_directory("cache_failure");
  GmshJob           broken;
  broken.name   = "broken.prm";
  broken.script = "Point(1) = {0, 0, 0};\nLine(1) = {1, 7};\n"; // point 7 does not exist
  GmshMesher mesher(dir + "/cache");
  CHECK_THROWS_WITH(mesher.mesh(broken), Contains("broken.prm") && Contains("gmsh failed") &&
                                           Contains("Unknown control point 7"));
  CHECK_THROWS_AS(mesher.mesh(broken), softchain::data::InputError);
  CHECK(mesher.n_runs() == 2); // the failed run left no cached mesh

  GmshMesher missing(dir + "/cache", dir + "/no_such_gmsh");
  GmshJob    fine = broken;
  fine.script     = "Point(1) = {0, 0, 0};\n";
  CHECK_THROWS_WITH(missing.mesh(fine), Contains("no_such_gmsh"));
}
