// The three shipped designs, meshed at the coarse resolution with tetrahedra
// and with hexahedra: volumes against the analytic shape, the cavity closed,
// the groups present, every spring node inside the silicone.
#include <softchain/geometry/cavity_surface.h>
#include <softchain/geometry/cell_geometry.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/mesh_checks.h>
#include <softchain/geometry/msh_file.h>
#include <softchain/geometry/point_locator.h>
#include <softchain/geometry/spring_network_file.h>

#include <Eigen/Geometry> // cross products
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include "test_files.h"

using namespace softchain::geometry;
using namespace softchain::geometry::testing;

namespace
{
  // Every face of the parametric shapes is planar and gmsh puts the surface
  // nodes on those planes, so the mesh reproduces the analytic volumes up to
  // round-off: coordinates carry ~16 significant digits (msh 2.2 text) and
  // summing ~1e4 cell volumes adds ~1e-15 relative each (measured: at most
  // 7e-15, benchmarks/mesh_generation). 1e-12 leaves a 100x margin while a
  // single misplaced boundary node or missing cell (>= 1e-5 relative at the
  // coarse resolution) fails.
  constexpr double planar_volume_tolerance = 1e-12;

  struct Meshed
  {
    FingerDesign    design;
    GeneratedDesign generated;
    MshFile         mesh;
  };

  // `test` keeps the scratch directories of test cases apart (ctest -j).
  Meshed mesh_design(const std::string &test, const std::string &name,
                     const std::string &element_shape, const std::string &wall_layers = "1",
                     const std::vector<std::pair<std::string, std::string>> &p10_changes = {})
  {
    const std::string dir = scratch_directory(test + "_" + name + "_" + element_shape);
    std::vector<std::pair<std::string, std::string>> changes{{"Resolution", "0"},
                                                             {"Element shape", element_shape}};
    if (wall_layers != "1") // only p10.prm names the entry
      changes.push_back({"Wall layers", wall_layers});
    changes.insert(changes.end(), p10_changes.begin(), p10_changes.end());
    const std::string prm = design_variant(name, dir, changes);
    GmshMesher mesher(dir + "/cache");
    Meshed     m{FingerDesign::read(prm), {}, {}};
    m.generated = generate_design(m.design, mesher);
    m.mesh      = MshFile::read(m.generated.mesh_file);
    return m;
  }
} // namespace

TEST_CASE("parametric designs match their analytic volumes", "[geometry][mesh]")
{
  const auto name          = GENERATE(as<std::string>{}, "p10", "p13", "parallelepiped");
  const auto element_shape = GENERATE(as<std::string>{}, "tet", "hex");
  CAPTURE(name, element_shape);
  const Meshed            m = mesh_design("volumes", name, element_shape);
  const FingerDimensions &d = m.design.dimensions;

  CHECK(CellGeometry::total_volume(m.mesh) ==
        Approx(d.material_volume()).epsilon(planar_volume_tolerance));
  const CavitySurface cavity(m.mesh);
  CHECK(cavity.enclosed_volume() == Approx(d.cavity_volume()).epsilon(planar_volume_tolerance));
  // Closed: the area vectors cancel (round-off only, see MeshChecks).
  CHECK(cavity.area_vector_sum().norm() < 1e-9 * cavity.total_area());
  CHECK(m.generated.length == d.length);

  const std::size_t corners = element_shape == "hex" ? 8 : 4;
  for (const auto &cell : m.mesh.cells)
    REQUIRE(cell.nodes.size() == corners);

  // The estimate that refuses meshes too fine to make: hexahedra exactly,
  // tetrahedra a lower bound (measured: HXT makes 3.9-5.9 times as many at
  // this resolution; below an eighth the refusal would come far too late).
  const double cells = static_cast<double>(m.mesh.cells.size());
  CAPTURE(cells, m.design.estimated_cells());
  if (element_shape == "hex")
    CHECK(m.design.estimated_cells() == cells);
  else
    CHECK((m.design.estimated_cells() <= cells && m.design.estimated_cells() >= cells / 8));
}

// The hexahedral grid of meshes/finger.geo has, per direction and block,
// ceil(block length / size) cells, and at least `Wall layers` across the
// walls and the bottom layer; the cavity block is left out. P10 at 8 mm:
// 2 + 10 + 1 cells along x, (1, 2, 1) across y and z with one layer (168
// hexahedra, measured in the solver's log), (2, 2, 2) with two (428). Each
// count is checked against that formula, so a layer lost or added anywhere
// fails; so does a wall layer that is not d / layers thick.
TEST_CASE("Wall layers puts that many hexahedra across each wall", "[geometry][mesh]")
{
  for (const int layers : {1, 2, 3})
    {
      const Meshed            m = mesh_design("layers" + std::to_string(layers), "p10", "hex",
                                              std::to_string(layers));
      const FingerDimensions &d = m.design.dimensions;
      const double            s = m.design.mesh_size();
      const auto cells = [&](double length) { return static_cast<int>(std::ceil(length / s - 1e-12)); };
      const int  n_fill = cells(d.base_fill), n_cap = cells(d.tip_cap);
      const int  n_cavity = cells(d.length - d.base_fill - d.tip_cap);
      const int  across_y = cells(std::max(d.base_height, d.tip_height) - d.wall - d.bottom);
      const int  across_z = cells(std::max(d.base_width, d.tip_width) - 2 * d.wall);
      const int  ny = std::max(layers, cells(d.bottom)) + across_y + std::max(layers, cells(d.wall));
      const int  nz = 2 * std::max(layers, cells(d.wall)) + across_z;
      CAPTURE(layers);
      CHECK(static_cast<int>(m.mesh.cells.size()) ==
            (n_fill + n_cavity + n_cap) * ny * nz - n_cavity * across_y * across_z);
      // Node z coordinates at the base (to 1 nm: gmsh's transfinite
      // interpolation differs in the last digits): the side wall's are
      // d / layers apart.
      std::set<long> z_at_base;
      for (const auto &p : m.mesh.nodes)
        if (p.x() == 0.0 && p.z() < -0.5 * d.base_width + d.wall + 1e-9)
          z_at_base.insert(std::lround(p.z() * 1e9));
      REQUIRE(static_cast<int>(z_at_base.size()) == std::max(layers, cells(d.wall)) + 1);
      for (auto z = z_at_base.begin(); std::next(z) != z_at_base.end(); ++z)
        CHECK(std::abs((*std::next(z) - *z) * 1e-9 - d.wall / (z_at_base.size() - 1)) <= 2e-9);
    }
}

// `Mesh sizes along the finger` changes the cells along x only: P10 with
// 4 mm across and 8 mm along has the 8 mm mesh's 2 + 10 + 1 cells along x
// and the 4 mm mesh's section, and its nodes along the top edge are
// (L - fill - cap) / 10 apart over the cavity.
TEST_CASE("a size along the finger sets the cells along it alone", "[geometry][mesh]")
{
  const Meshed m = mesh_design("size_along", "p10", "hex", "2",
                               {{"Mesh sizes", "0.004, 0.004, 0.004"},
                                {"Mesh sizes along the finger", "0.008, 0.008, 0.008"}});
  const FingerDimensions &d = m.design.dimensions;
  const auto cells = [](double length, double size) { return static_cast<int>(std::ceil(length / size - 1e-12)); };
  const int  n_x      = cells(d.base_fill, 0.008) + cells(d.length - d.base_fill - d.tip_cap, 0.008) +
                   cells(d.tip_cap, 0.008);
  const int  n_cavity = cells(d.length - d.base_fill - d.tip_cap, 0.008);
  const int  across_y = cells(std::max(d.base_height, d.tip_height) - d.wall - d.bottom, 0.004);
  const int  across_z = cells(std::max(d.base_width, d.tip_width) - 2 * d.wall, 0.004);
  const int  ny       = std::max(2, cells(d.bottom, 0.004)) + across_y + std::max(2, cells(d.wall, 0.004));
  const int  nz       = 2 * std::max(2, cells(d.wall, 0.004)) + across_z;
  REQUIRE(n_x == 13);
  CHECK(static_cast<int>(m.mesh.cells.size()) == n_x * ny * nz - n_cavity * across_y * across_z);
  CHECK(m.design.estimated_cells() == static_cast<double>(m.mesh.cells.size()));
  // The base's bottom edge (y = 0, z = -w/2): nodes at x = fill + k (L - fill - cap) / 10 over
  // the cavity (to 1 nm, gmsh's transfinite interpolation).
  std::set<long> x_on_edge;
  for (const auto &p : m.mesh.nodes)
    if (p.y() == 0.0 && std::abs(p.z() + 0.5 * (d.base_width + (d.tip_width - d.base_width) * p.x() / d.length)) < 1e-9 &&
        p.x() > d.base_fill - 1e-9 && p.x() < d.length - d.tip_cap + 1e-9)
      x_on_edge.insert(std::lround(p.x() * 1e9));
  REQUIRE(static_cast<int>(x_on_edge.size()) == n_cavity + 1);
  const double step = (d.length - d.base_fill - d.tip_cap) / n_cavity;
  for (auto x = x_on_edge.begin(); std::next(x) != x_on_edge.end(); ++x)
    CHECK(std::abs((*std::next(x) - *x) * 1e-9 - step) <= 2e-9);
}

TEST_CASE("parametric meshes carry the physical groups", "[geometry][mesh]")
{
  const Meshed m = mesh_design("groups", "p10", "tet");
  for (const char *name : {"base", "cavity", "tip"})
    CHECK(m.mesh.has_group(name, 2));
  CHECK(m.mesh.has_group("silicone", 3));
  // base and tip facets lie on x = 0 and x = L.
  for (const auto &[group, x] : {std::pair{"base", 0.0}, std::pair{"tip", m.design.dimensions.length}})
    for (const MshElement *facet : m.mesh.facets_of(group))
      for (const std::size_t n : facet->nodes)
        REQUIRE(m.mesh.nodes[n].x() == Approx(x).margin(1e-12));
}

TEST_CASE("cavity triangles point out of the silicone, into the cavity", "[geometry][mesh]")
{
  const Meshed            m = mesh_design("orientation", "parallelepiped", "tet");
  const FingerDimensions &d = m.design.dimensions;
  const CavitySurface     cavity(m.mesh);
  const Eigen::Vector3d   centre(0.5 * (d.cavity_start() + d.cavity_end()),
                               0.5 * (d.bottom + d.base_height - d.wall), 0.0);
  // The cavity is a box: each inward facet normal points toward its centre.
  for (const auto &t : cavity.triangles())
    {
      const Eigen::Vector3d x0 = m.mesh.nodes[t[0]];
      const Eigen::Vector3d n  = (m.mesh.nodes[t[1]] - x0).cross(m.mesh.nodes[t[2]] - x0);
      REQUIRE(n.dot(centre - x0) > 0.0);
    }
}

TEST_CASE("every spring node lies inside the silicone of the mesh", "[geometry][springs]")
{
  const auto name = GENERATE(as<std::string>{}, "p10", "p13", "parallelepiped");
  CAPTURE(name);
  const Meshed m        = mesh_design("springs", name, "tet");
  const auto   networks = SpringNetworkFile::read(m.generated.spring_file);
  REQUIRE(networks.size() == 2);
  const PointLocator locator(m.mesh);
  for (const auto &network : networks)
    {
      CHECK(network.n_nodes() > 0);
      for (const auto &polyline : network.polylines)
        for (const auto &p : polyline.points)
          {
            REQUIRE(m.design.dimensions.material_margin(p) > 0.0);
            REQUIRE(locator.locate(p).has_value());
          }
    }
}
