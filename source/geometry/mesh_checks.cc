#include <softchain/data/input_error.h>
#include <softchain/geometry/cavity_surface.h>
#include <softchain/geometry/cell_geometry.h>
#include <softchain/geometry/mesh_checks.h>
#include <softchain/geometry/point_locator.h>

#include <cmath>
#include <sstream>

namespace softchain::geometry
{
  namespace
  {
    using data::InputError;

    // A tetrahedron is degenerate below this volume / (longest edge)^3; a
    // regular one has 0.118, gmsh's worst slivers after optimisation ~1e-3.
    constexpr double degenerate_volume_ratio = 1e-6;
    // A closed triangulated surface has area vectors summing to exactly zero;
    // only round-off (~1e-16 per facet) remains.
    constexpr double closed_surface_tolerance = 1e-9;

    double longest_edge(const std::vector<Eigen::Vector3d> &nodes, const CellGeometry::Tetrahedron &t)
    {
      double longest = 0.0;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          longest = std::max(longest, (nodes[t[a]] - nodes[t[b]]).norm());
      return longest;
    }

    std::string text(double value)
    {
      std::ostringstream s;
      s << value;
      return s.str();
    }

    std::string point_text(const Eigen::Vector3d &p)
    {
      return "(" + text(p.x()) + ", " + text(p.y()) + ", " + text(p.z()) + ")";
    }

    void check_cell(const MshFile &mesh, const MshElement &cell)
    {
      for (const auto &t : CellGeometry::tetrahedra(cell))
        {
          const double v     = CellGeometry::signed_volume(mesh.nodes, t);
          const double scale = std::pow(longest_edge(mesh.nodes, t), 3);
          if (std::abs(v) <= degenerate_volume_ratio * scale)
            throw InputError(mesh.path + ": element " + std::to_string(cell.id) +
                             " is degenerate (volume " + text(v) + " m^3)");
          if (v < 0.0)
            throw InputError(mesh.path + ": element " + std::to_string(cell.id) +
                             " is inverted (negative volume)");
        }
    }
  } // namespace

  void MeshChecks::require_groups(const MshFile &mesh)
  {
    for (const char *name : {"base", "cavity", "tip"})
      if (!mesh.has_group(name, 2))
        throw InputError(mesh.path + ": the surface physical group '" + name + "' is missing");
    if (!mesh.has_group("silicone", 3))
      throw InputError(mesh.path + ": the volume physical group 'silicone' is missing");
  }

  void MeshChecks::check_cells(const MshFile &mesh)
  {
    for (const auto &cell : mesh.cells)
      check_cell(mesh, cell);
  }

  void MeshChecks::check_cavity_closed(const MshFile &mesh)
  {
    const CavitySurface cavity(mesh);
    const double        gap = cavity.area_vector_sum().norm();
    if (cavity.triangles().empty() || gap > closed_surface_tolerance * cavity.total_area())
      throw InputError(mesh.path + ": the cavity surface is not closed (area vectors sum to " +
                       text(gap) + " m^2 of " + text(cavity.total_area()) + " m^2)");
  }

  void MeshChecks::check_springs_inside(const MshFile &mesh, const std::vector<SpringNetwork> &networks,
                                        const std::string &spring_source)
  {
    const PointLocator locator(mesh);
    const auto         check = [&](const Eigen::Vector3d &p, const std::string &what, std::size_t k,
                           const SpringNetwork &network) {
      if (!locator.locate(p))
        throw InputError(spring_source + ": " + what + " " + point_text(p) + " of " +
                         (what == "node" ? "polyline " : "sheet ") + std::to_string(k + 1) +
                         " of network '" + network.name + "' lies outside the body mesh " + mesh.path);
    };
    for (const auto &network : networks)
      {
        for (std::size_t l = 0; l < network.polylines.size(); ++l)
          for (const auto &p : network.polylines[l].points)
            check(p, "node", l, network);
        for (std::size_t l = 0; l < network.sheets.size(); ++l)
          for (const auto &p : network.sheets[l].corners)
            check(p, "corner", l, network);
      }
  }

  void MeshChecks::check_all(const MshFile &mesh, const std::vector<SpringNetwork> &networks,
                             const std::string &spring_source)
  {
    require_groups(mesh);
    check_cells(mesh);
    check_cavity_closed(mesh);
    check_springs_inside(mesh, networks, spring_source);
  }
} // namespace softchain::geometry
