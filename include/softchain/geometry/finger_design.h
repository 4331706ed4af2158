#pragma once
// FingerDesign: the .prm subsection "Finger design", checked. A design is
// either parametric (Shape = p10 | p13 | parallelepiped, meshed from
// meshes/finger.geo with the dimensions below) or imported (Shape = stl: two
// closed STL surfaces, outer body and cavity, with the base and tip faces
// found on the planes x = Base plane x and x = Tip plane x).
#include <softchain/geometry/finger_dimensions.h>

#include <softchain/data/prm_file.h>

#include <array>
#include <string>

namespace softchain::geometry
{
  // Where the fabric grid and the thread rings go (parametric designs).
  struct SpringLayout
  {
    double fabric_height       = 0.0015; // y of the fabric grid, inside the bottom layer, m
    double fabric_spacing      = 0.002;  // grid spacing of the fabric springs, m
    double thread_pitch        = 0.005;  // distance between thread rings along x, m
    double thread_node_spacing = 0.002;  // node spacing along a ring, m
  };

  // An imported design (Shape = stl). Paths are relative to the .prm file.
  struct SurfaceDesign
  {
    std::string outer_file;  // closed STL of the outer body surface
    std::string cavity_file; // closed STL of the cavity surface
    std::string spring_file; // optional spring network file (may be empty)
    double      base_x          = 0.0;  // plane of the clamped base face, m
    double      tip_x           = 0.09; // plane of the tip face, m
    double      plane_tolerance = 1e-6; // |x - plane| for a vertex on a plane, m
  };

  class FingerDesign
  {
  public:
    // Parses the subsection "Finger design" of a .prm file (other
    // subsections are ignored). Throws InputError naming file, line and
    // parameter.
    static FingerDesign read(const data::PrmFile &file);
    // Reads the .prm file at `prm_path` and parses it as above.
    static FingerDesign read(const std::string &prm_path);

    // The paper's three parametric fingers differ only in their dimensions;
    // a parallelepiped's tip section equals its base section; `stl` is a
    // surface from a file.
    enum class Shape
    {
      p10,
      p13,
      parallelepiped,
      stl
    };

    std::string      source;      // the .prm path, for messages
    Shape            shape = Shape::p10;
    int              resolution = 1; // 0 coarse, 1 default, 2 fine
    bool             hexahedra  = false;
    std::array<double, 3> mesh_sizes{{0.008, 0.004, 0.0018}}; // m, per resolution
    // Hexahedra: the element size along the finger (x) per resolution, where
    // it differs from mesh_sizes (0: the same); the walls' bending is resolved
    // across the section, so an accurate mesh needs finer sections than
    // intervals along the finger (docs/fem_accuracy.md).
    std::array<double, 3> mesh_sizes_along{{0.0, 0.0, 0.0}};
    // Hexahedra: at least this many elements across each wall and the bottom
    // layer, however large the elements along the finger.
    int              wall_layers = 1;
    FingerDimensions dimensions;
    SpringLayout     springs;
    // Parametric shapes: the fabric and threads as the paper's 1D springs
    // (false) or homogenised over sheets (true; Reinforcement).
    bool             fibre_sheets = false;
    SurfaceDesign    surface;

    bool   parametric() const { return shape != Shape::stl; }
    double mesh_size() const { return mesh_sizes.at(resolution); } // m
    // m, along the finger: mesh_size() unless Mesh sizes along the finger sets it
    double mesh_size_along() const
    {
      return mesh_sizes_along.at(resolution) > 0.0 ? mesh_sizes_along.at(resolution) : mesh_size();
    }
    double length() const; // tip abscissa minus base abscissa
    // Parametric shapes: the cells meshes/finger.geo makes at the resolution,
    // hexahedra exactly; tetrahedra a lower bound, the material filled with
    // regular ones of edge mesh_size() (no tetrahedron whose edges are at most
    // that is larger): HXT made 3.9 to 5.9 times as many for the three
    // designs at 8 mm, whose walls are thinner than that.
    double estimated_cells() const;
    // More cells than a design may ask for: far beyond what a solve on one
    // machine holds (P10 on hexahedra of 2 mm with two layers has 4,000), so
    // that a size mistyped by a few orders of magnitude is refused at once
    // instead of meshing for hours.
    static constexpr double max_cells = 1e6;
  };
} // namespace softchain::geometry
