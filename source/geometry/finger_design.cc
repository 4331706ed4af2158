#include <softchain/data/content_hash.h>
#include <softchain/data/input_error.h>
#include <softchain/data/prm_file.h>
#include <softchain/geometry/finger_design.h>
#include <softchain/geometry/text_lines.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace softchain::geometry
{
  namespace
  {
    using data::InputError;
    using data::PrmSection;

    const char *const subsection = "Finger design";

    // Parameter name and where its value goes; the default comes from the
    // member initialisers of FingerDimensions (the P10).
    const std::vector<std::pair<const char *, double FingerDimensions::*>> dimension_entries = {
      {"Length", &FingerDimensions::length},
      {"Base width", &FingerDimensions::base_width},
      {"Base height", &FingerDimensions::base_height},
      {"Tip width", &FingerDimensions::tip_width},
      {"Tip height", &FingerDimensions::tip_height},
      {"Wall thickness", &FingerDimensions::wall},
      {"Bottom layer thickness", &FingerDimensions::bottom},
      {"Base fill length", &FingerDimensions::base_fill},
      {"Tip cap thickness", &FingerDimensions::tip_cap}};

    const std::vector<std::pair<const char *, double SpringLayout::*>> spring_entries = {
      {"Fabric height", &SpringLayout::fabric_height},
      {"Fabric spacing", &SpringLayout::fabric_spacing},
      {"Thread pitch", &SpringLayout::thread_pitch},
      {"Thread node spacing", &SpringLayout::thread_node_spacing}};

    std::string number(double v)
    {
      return data::canonical(v);
    }

    void declare(PrmSection &section)
    {
      section.declare("Shape", "p10", "p10 | p13 | parallelepiped | stl");
      section.declare("Resolution", "1", "0 coarse (tests), 1 default, 2 fine");
      section.declare("Element shape", "tet", "tet | hex (hex: parametric shapes only)");
      const auto sizes = FingerDesign().mesh_sizes;
      section.declare("Mesh sizes",
                      number(sizes[0]) + ", " + number(sizes[1]) + ", " + number(sizes[2]),
                      "largest element size (m) at resolution 0, 1, 2");
      section.declare("Mesh sizes along the finger", "",
                      "hex: element size (m) along the finger at resolution 0, 1, 2; "
                      "empty: Mesh sizes");
      section.declare("Wall layers", "1",
                      "hex: at least this many elements across the walls and the bottom layer");
      for (const auto &[name, member] : dimension_entries)
        section.declare(name, number(FingerDimensions().*member), "m");
      for (const auto &[name, member] : spring_entries)
        section.declare(name, number(SpringLayout().*member), "m");
      section.declare("Reinforcement", "springs",
                      "springs (the paper's 1D springs) | sheets (the same fibres homogenised)");
      const SurfaceDesign surface;
      section.declare("Outer surface file", "", "Shape = stl: closed STL of the outer body");
      section.declare("Cavity surface file", "", "Shape = stl: closed STL of the cavity");
      section.declare("Spring file", "", "Shape = stl: spring networks (optional)");
      section.declare("Base plane x", number(surface.base_x), "Shape = stl: base face plane, m");
      section.declare("Tip plane x", number(surface.tip_x), "Shape = stl: tip face plane, m");
      section.declare("Plane tolerance", number(surface.plane_tolerance), "m");
    }

    void require(bool condition, const PrmSection &section, const std::string &name,
                 const std::string &what)
    {
      if (!condition)
        throw InputError(section.describe(name) + " = " + section.get(name) + ": " + what);
    }

    double positive(const PrmSection &section, const std::string &name)
    {
      const double v = section.get_double(name);
      require(v > 0.0, section, name, "must be positive");
      return v;
    }

    void read_mesh_choice(const PrmSection &section, FingerDesign &design)
    {
      using Shape  = FingerDesign::Shape;
      design.shape = section.get_enum<Shape>("Shape", {{"p10", Shape::p10},
                                                       {"p13", Shape::p13},
                                                       {"parallelepiped", Shape::parallelepiped},
                                                       {"stl", Shape::stl}});
      design.resolution = section.get_integer("Resolution");
      require(design.resolution >= 0 && design.resolution <= 2, section, "Resolution",
              "expected 0, 1 or 2");
      const std::string element = section.get("Element shape");
      require(element == "tet" || element == "hex", section, "Element shape", "expected tet or hex");
      design.hexahedra = element == "hex";
      require(!design.hexahedra || design.parametric(), section, "Element shape",
              "hexahedra need a parametric shape, not stl");
      const std::vector<double> sizes = section.get_double_list("Mesh sizes");
      require(sizes.size() == 3 && *std::min_element(sizes.begin(), sizes.end()) > 0.0, section,
              "Mesh sizes", "expected three positive sizes (resolution 0, 1, 2)");
      std::copy(sizes.begin(), sizes.end(), design.mesh_sizes.begin());
      const std::vector<double> along = section.get_double_list("Mesh sizes along the finger");
      require(along.empty() || (along.size() == 3 && *std::min_element(along.begin(), along.end()) > 0.0),
              section, "Mesh sizes along the finger",
              "expected nothing or three positive sizes (resolution 0, 1, 2)");
      require(along.empty() || design.hexahedra, section, "Mesh sizes along the finger",
              "a size along the finger needs Element shape = hex");
      std::copy(along.begin(), along.end(), design.mesh_sizes_along.begin());
      design.wall_layers = section.get_integer("Wall layers");
      require(design.wall_layers >= 1 && design.wall_layers <= 8, section, "Wall layers",
              "expected 1 to 8 elements across a wall");
      require(design.wall_layers == 1 || design.hexahedra, section, "Wall layers",
              "layers across the walls need Element shape = hex");
    }

    void check_cavity_fits(const PrmSection &section, const FingerDimensions &d)
    {
      require(d.base_fill + d.tip_cap < d.length, section, "Base fill length",
              "base fill plus tip cap leave no cavity in the length");
      require(std::min(d.base_width, d.tip_width) > 2.0 * d.wall, section, "Wall thickness",
              "two walls are as wide as the finger: no cavity");
      require(std::min(d.base_height, d.tip_height) > d.wall + d.bottom, section,
              "Bottom layer thickness", "bottom layer and top wall fill the height: no cavity");
    }

    void read_parametric(const PrmSection &section, FingerDesign &design)
    {
      for (const auto &[name, member] : dimension_entries)
        design.dimensions.*member = positive(section, name);
      for (const auto &[name, member] : spring_entries)
        design.springs.*member = positive(section, name);
      const std::string reinforcement = section.get("Reinforcement");
      require(reinforcement == "springs" || reinforcement == "sheets", section, "Reinforcement",
              "expected springs or sheets");
      design.fibre_sheets = reinforcement == "sheets";
      check_cavity_fits(section, design.dimensions);
      require(design.springs.fabric_height < design.dimensions.bottom, section, "Fabric height",
              "the fabric must lie inside the bottom layer (below Bottom layer thickness)");
      const FingerDimensions &d = design.dimensions;
      require(design.shape != FingerDesign::Shape::parallelepiped ||
                (d.tip_width == d.base_width && d.tip_height == d.base_height),
              section, "Tip width", "a parallelepiped has Tip width/height = Base width/height");
    }

    void check_cell_count(const PrmSection &section, const FingerDesign &design)
    {
      const double cells = design.estimated_cells();
      if (cells <= FingerDesign::max_cells)
        return;
      const std::string name = design.mesh_size_along() < design.mesh_size() ? "Mesh sizes along the finger" :
                                                                                "Mesh sizes";
      std::ostringstream what;
      what << (design.hexahedra ? "" : "at least ") << std::setprecision(2) << cells
           << (design.hexahedra ? " hexahedra" : " tetrahedra")
           << " at Resolution " << design.resolution << ", more than the "
           << static_cast<long>(FingerDesign::max_cells) << " a design may have (sizes are in metres)";
      require(false, section, name, what.str());
    }

    void read_surface(const PrmSection &section, FingerDesign &design)
    {
      SurfaceDesign &s = design.surface;
      require(!section.get("Outer surface file").empty(), section, "Outer surface file",
              "Shape = stl needs the outer surface");
      require(!section.get("Cavity surface file").empty(), section, "Cavity surface file",
              "Shape = stl needs the cavity surface");
      s.outer_file      = TextLines::beside(design.source, section.get("Outer surface file"));
      s.cavity_file     = TextLines::beside(design.source, section.get("Cavity surface file"));
      s.spring_file     = TextLines::beside(design.source, section.get("Spring file"));
      s.base_x          = section.get_double("Base plane x");
      s.tip_x           = section.get_double("Tip plane x");
      s.plane_tolerance = positive(section, "Plane tolerance");
      require(s.tip_x > s.base_x, section, "Tip plane x", "must be larger than Base plane x");
    }
  } // namespace

  FingerDesign FingerDesign::read(const data::PrmFile &file)
  {
    PrmSection section;
    declare(section);
    file.parse_section(subsection, section);
    FingerDesign design;
    design.source = file.path();
    read_mesh_choice(section, design);
    if (design.parametric())
      {
        read_parametric(section, design);
        check_cell_count(section, design);
      }
    else
      read_surface(section, design);
    return design;
  }

  FingerDesign FingerDesign::read(const std::string &prm_path)
  {
    return read(data::PrmFile::read(prm_path));
  }

  double FingerDesign::estimated_cells() const
  {
    const FingerDimensions &d = dimensions;
    const double            s = mesh_size();
    if (!hexahedra)
      return 6.0 * std::sqrt(2.0) * d.material_volume() / (s * s * s);
    // meshes/finger.geo: ceil(block length / size) cells per block and
    // direction, at least `layers` across the walls and the bottom layer.
    const auto   cells = [](double length, double size) { return std::ceil(length / size - 1e-12); };
    const double a = mesh_size_along(), layers = wall_layers;
    const double cavity = cells(d.length - d.base_fill - d.tip_cap, a);
    const double nx     = cells(d.base_fill, a) + cavity + cells(d.tip_cap, a);
    const double across_y = cells(std::max(d.base_height, d.tip_height) - d.wall - d.bottom, s);
    const double across_z = cells(std::max(d.base_width, d.tip_width) - 2 * d.wall, s);
    const double ny = std::max(layers, cells(d.bottom, s)) + across_y + std::max(layers, cells(d.wall, s));
    const double nz = 2 * std::max(layers, cells(d.wall, s)) + across_z;
    return nx * ny * nz - cavity * across_y * across_z;
  }

  double FingerDesign::length() const
  {
    return parametric() ? dimensions.length : surface.tip_x - surface.base_x;
  }
} // namespace softchain::geometry
