#pragma once
// SurfaceImport: a design given as two closed STL surfaces (outer body and
// cavity), as in the paper's pipeline ("a low resolution surface mesh,
// including the pressure cavity"). The outer surface is split into the base
// face (all vertices on x = base_x), the tip face (x = tip_x) and the rest;
// all surfaces are refined by edge-midpoint subdivision until no edge is
// longer than twice the mesh size, and meshes/surface_import.geo fills the
// volume between them with tetrahedra, with the physical groups base, tip,
// cavity and silicone of the parametric designs.
#include <softchain/geometry/finger_design.h>
#include <softchain/geometry/gmsh_mesher.h>
#include <softchain/geometry/stl_file.h>

namespace softchain::geometry
{
  class SurfaceImport
  {
  public:
    // The gmsh job of an imported design; throws InputError naming the STL
    // file if a plane holds no triangle of the outer surface.
    static GmshJob job(const FingerDesign &design);

  private:
    static StlFile triangles_on_plane(const StlFile &outer, double x, double tolerance,
                                      bool wanted);
    // Subdivision levels that bring the longest edge to at most twice the mesh size.
    static int levels(const StlFile &surface, double mesh_size);
  };
} // namespace softchain::geometry
