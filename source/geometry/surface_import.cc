#include <softchain/data/input_error.h>
#include <softchain/geometry/surface_import.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace softchain::geometry
{
  namespace
  {
    // Subdivision levels are capped: 4^6 = 4096 triangles per input triangle.
    constexpr int max_levels = 6;

    bool on_plane(const StlFile::Triangle &t, double x, double tolerance)
    {
      return std::all_of(t.begin(), t.end(),
                         [&](const Eigen::Vector3d &v) { return std::abs(v.x() - x) <= tolerance; });
    }
  } // namespace

  StlFile SurfaceImport::triangles_on_plane(const StlFile &outer, double x, double tolerance,
                                            bool wanted)
  {
    StlFile part;
    std::copy_if(outer.triangles.begin(), outer.triangles.end(), std::back_inserter(part.triangles),
                 [&](const StlFile::Triangle &t) { return on_plane(t, x, tolerance) == wanted; });
    return part;
  }

  int SurfaceImport::levels(const StlFile &surface, double mesh_size)
  {
    // Each level halves the longest edge; stop at twice the mesh size.
    const double ratio = surface.longest_edge() / (2.0 * mesh_size);
    const int    n     = ratio > 1.0 ? static_cast<int>(std::ceil(std::log2(ratio))) : 0;
    return std::min(n, max_levels);
  }

  GmshJob SurfaceImport::job(const FingerDesign &design)
  {
    const SurfaceDesign &s      = design.surface;
    const StlFile        outer  = StlFile::read(s.outer_file);
    const StlFile        cavity = StlFile::read(s.cavity_file);
    const StlFile        base   = triangles_on_plane(outer, s.base_x, s.plane_tolerance, true);
    const StlFile        tip    = triangles_on_plane(outer, s.tip_x, s.plane_tolerance, true);
    for (const auto &[part, x, what] : {std::tuple{&base, s.base_x, "Base plane x"},
                                       std::tuple{&tip, s.tip_x, "Tip plane x"}})
      if (part->triangles.empty())
        throw data::InputError(s.outer_file + ": no triangle lies on the plane x = " +
                               std::to_string(x) + " (" + what + " in " + design.source + ")");
    const StlFile side = triangles_on_plane(
      triangles_on_plane(outer, s.base_x, s.plane_tolerance, false), s.tip_x, s.plane_tolerance, false);
    // One level for all pieces of the outer surface keeps them conforming.
    const int outer_levels = levels(outer, design.mesh_size());
    GmshJob   job;
    job.name    = design.source;
    job.script  = GmshJob::bundled_script("surface_import.geo");
    job.numbers = {{"size", design.mesh_size()}};
    job.files   = {{"outer_side.stl", side.subdivided(outer_levels).ascii_text()},
                   {"base.stl", base.subdivided(outer_levels).ascii_text()},
                   {"tip.stl", tip.subdivided(outer_levels).ascii_text()},
                   {"cavity.stl", cavity.subdivided(levels(cavity, design.mesh_size())).ascii_text()}};
    return job;
  }
} // namespace softchain::geometry
