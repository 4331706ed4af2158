// MeshChecks on hand-written small meshes and on a damaged real one: each
// defect is an InputError that names what is wrong.
#include <softchain/data/input_error.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/mesh_checks.h>

#include <catch2/catch.hpp>

#include <algorithm>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;
using softchain::data::InputError;
using Catch::Matchers::Contains;

namespace
{
  const std::string all_groups = "4\n2 1 \"base\"\n2 2 \"cavity\"\n2 3 \"tip\"\n3 4 \"silicone\"\n";

  // Unit corner tetrahedron (nodes 1-4), node 5 above it, node 6 in its
  // bottom face; `elements` are msh 2.2 element lines.
  MshFile small_mesh(const std::string &name, const std::string &groups, const std::string &elements)
  {
    const std::string path = scratch_directory("checks_" + name) + "/" + name + ".msh";
    const auto        n    = std::count(elements.begin(), elements.end(), '\n');
    write_text(path, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" + groups +
                       "$EndPhysicalNames\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                       "5 1 1 1\n6 0.5 0.5 0\n$EndNodes\n$Elements\n" +
                       std::to_string(n) + "\n" + elements + "$EndElements\n");
    return MshFile::read(path);
  }

  const std::string good_cells = "2 4 2 4 1 1 2 3 4\n3 4 2 4 1 2 3 4 5\n";
} // namespace

TEST_CASE("well-formed cells pass, inverted and degenerate ones are named", "[geometry][checks]")
{
  CHECK_NOTHROW(MeshChecks::check_cells(small_mesh("good", all_groups, good_cells)));
  // Element 3 with two nodes swapped: negative volume.
  const MshFile inverted = small_mesh("inverted", all_groups, "2 4 2 4 1 1 2 3 4\n3 4 2 4 1 3 2 4 5\n");
  CHECK_THROWS_WITH(MeshChecks::check_cells(inverted), Contains("element 3") && Contains("inverted"));
  // Element 7 has four nodes in the plane z = 0.
  const MshFile flat = small_mesh("flat", all_groups, good_cells + "7 4 2 4 1 1 2 3 6\n");
  CHECK_THROWS_WITH(MeshChecks::check_cells(flat), Contains("element 7") && Contains("degenerate"));
}

TEST_CASE("a missing physical group is named", "[geometry][checks]")
{
  CHECK_NOTHROW(MeshChecks::require_groups(small_mesh("groups", all_groups, good_cells)));
  const MshFile no_tip = small_mesh(
    "no_tip", "3\n2 1 \"base\"\n2 2 \"cavity\"\n3 4 \"silicone\"\n", good_cells);
  CHECK_THROWS_WITH(MeshChecks::require_groups(no_tip), Contains("'tip'") && Contains("no_tip.msh"));
  const MshFile no_volume = small_mesh(
    "no_volume", "3\n2 1 \"base\"\n2 2 \"cavity\"\n2 3 \"tip\"\n", good_cells);
  CHECK_THROWS_WITH(MeshChecks::require_groups(no_volume), Contains("'silicone'"));
}

TEST_CASE("an open cavity surface is refused", "[geometry][checks]")
{
  // One face of a tetrahedron is not a closed surface.
  const MshFile one_face = small_mesh("open", all_groups, "1 2 2 2 1 1 3 2\n" + good_cells);
  CHECK_THROWS_WITH(MeshChecks::check_cavity_closed(one_face), Contains("not closed"));

  // A real cavity with a single facet removed out of hundreds.
  const std::string dir  = scratch_directory("checks_real_cavity");
  GmshMesher        mesher(dir + "/cache");
  MshFile           mesh = MshFile::read(
    generate_design(FingerDesign::read(design_variant("p10", dir, {{"Resolution", "0"}})), mesher)
      .mesh_file);
  CHECK_NOTHROW(MeshChecks::check_cavity_closed(mesh));
  const int  cavity = mesh.groups.at("cavity").tag;
  const auto facet  = std::find_if(mesh.facets.begin(), mesh.facets.end(),
                                  [&](const MshElement &f) { return f.physical == cavity; });
  REQUIRE(facet != mesh.facets.end());
  mesh.facets.erase(facet);
  CHECK_THROWS_WITH(MeshChecks::check_cavity_closed(mesh), Contains("not closed"));
}

TEST_CASE("a spring node outside the body is named", "[geometry][checks]")
{
  const MshFile mesh = small_mesh("springs", all_groups, good_cells);
  SpringNetwork inside{"fabric", {{false, {{0.1, 0.1, 0.1}, {0.5, 0.5, 0.5}}}}, {}};
  CHECK_NOTHROW(MeshChecks::check_springs_inside(mesh, {inside}, "springs.txt"));
  SpringNetwork outside{"thread", {{true, {{0.1, 0.1, 0.1}, {0.9, 0.9, 0.1}}}}, {}};
  CHECK_THROWS_WITH(MeshChecks::check_springs_inside(mesh, {inside, outside}, "springs.txt"),
                    Contains("springs.txt") && Contains("'thread'") && Contains("0.9"));
  // A fibre sheet's corners, likewise.
  SpringNetwork sheet{"fabric", {}, {{{{0.1, 0.1, 0.1}, {0.5, 0.1, 0.1}, {0.5, 0.9, 0.8}},
                                      {{Eigen::Vector3d::UnitX(), 0.002}}}}};
  CHECK_THROWS_WITH(MeshChecks::check_springs_inside(mesh, {sheet}, "springs.txt"),
                    Contains("corner") && Contains("sheet 1") && Contains("'fabric'") && Contains("0.8"));
}

TEST_CASE("msh files other than ASCII 2.2 with first-order cells are refused", "[geometry][checks]")
{
  const std::string dir = scratch_directory("checks_format");
  write_text(dir + "/v4.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  CHECK_THROWS_WITH(MshFile::read(dir + "/v4.msh"), Contains("v4.msh:2") && Contains("msh 2"));
  CHECK_THROWS_AS(MshFile::read(dir + "/missing.msh"), InputError);
  // Type 11 is the second-order tetrahedron.
  CHECK_THROWS_WITH(small_mesh("quadratic", all_groups, "1 11 2 4 1 1 2 3 4 5 6 1 2 3 4\n"),
                    Contains("element type 11"));
}
