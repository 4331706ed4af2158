#include <softchain/fem/boundary_ids.h>
#include <softchain/fem/built_in_bender.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // Cell sizes across a wall-cavity-wall section of total size `total`.
    std::vector<double> wall_cavity_wall(const double total, const double wall,
                                         const unsigned int inner_cells)
    {
      std::vector<double> steps{wall};
      steps.insert(steps.end(), inner_cells, (total - 2 * wall) / inner_cells);
      steps.push_back(wall);
      return steps;
    }

    // Points from a to b (a included, b excluded) at most `spacing` apart.
    void sample_segment(const Point<3> &a, const Point<3> &b, const double spacing,
                        std::vector<Point<3>> &points)
    {
      const unsigned int n = std::max(1u, static_cast<unsigned int>(std::ceil(a.distance(b) / spacing)));
      for (unsigned int k = 0; k < n; ++k)
        points.push_back(a + (double(k) / n) * (b - a));
    }
  } // namespace

  BuiltInBender::BuiltInBender(const Parameters &prm)
    : length(prm.mesh.bender_length)
    , width(prm.mesh.bender_width)
    , height(prm.mesh.bender_height)
    , wall(prm.mesh.bender_wall)
    , cells_along_length(prm.mesh.bender_cells_length)
    , tetrahedra(is_simplex(prm.mesh.element_type))
    , refinements(prm.mesh.global_refinements)
    , with_springs(prm.springs.generate_for_bender)
    , thread_pitch(prm.springs.thread_pitch)
  {}

  double BuiltInBender::body_volume() const
  {
    return length * width * height - cavity_volume();
  }

  double BuiltInBender::cavity_volume() const
  {
    return (length - 2 * wall) * (width - 2 * wall) * (height - 2 * wall);
  }

  void BuiltInBender::build(FingerMesh &mesh) const
  {
    // Roughly cubic cells in the cavity region, one cell through each wall.
    const double       h       = (length - 2 * wall) / cells_along_length;
    const unsigned int n_y     = std::max(1u, unsigned(std::round((height - 2 * wall) / h)));
    const unsigned int n_z     = std::max(1u, unsigned(std::round((width - 2 * wall) / h)));
    const std::vector<std::vector<double>> steps{
      wall_cavity_wall(length, wall, cells_along_length), wall_cavity_wall(height, wall, n_y),
      wall_cavity_wall(width, wall, n_z)};
    Table<3, types::material_id> material(steps[0].size(), steps[1].size(), steps[2].size());
    for (unsigned int i = 0; i < material.size(0); ++i)
      for (unsigned int j = 0; j < material.size(1); ++j)
        for (unsigned int k = 0; k < material.size(2); ++k)
          {
            const bool inside = i > 0 && i + 1 < material.size(0) && j > 0 &&
                                j + 1 < material.size(1) && k > 0 && k + 1 < material.size(2);
            material(i, j, k) = inside ? numbers::invalid_material_id : 0;
          }
    Triangulation<3> hexes;
    GridGenerator::subdivided_hyper_rectangle(hexes, steps, Point<3>(),
                                              material, /*colorize*/ false);
    for (const auto &face : hexes.active_face_iterators())
      if (face->at_boundary())
        {
          const double x = face->center()[0];
          face->set_boundary_id(std::abs(x) < 1e-12 * length          ? boundary::base :
                                std::abs(x - length) < 1e-12 * length ? boundary::tip :
                                (std::abs(face->center()[1] - height / 2) < height / 2 - wall / 4 &&
                                 std::abs(face->center()[2] - width / 2) < width / 2 - wall / 4 &&
                                 x > wall / 4 && x < length - wall / 4) ?
                                                                        boundary::cavity :
                                                                        boundary::other);
        }
    hexes.refine_global(refinements);
    mesh.triangulation.clear();
    if (tetrahedra)
      GridGenerator::convert_hypercube_to_simplex_mesh(hexes, mesh.triangulation);
    else
      mesh.triangulation.copy_triangulation(hexes);
    mesh.material_names = {"silicone"};
    mesh.springs        = with_springs ? springs() : std::vector<SpringPolyline>();
    mesh.description    = "built-in hollow bender";
  }

  std::vector<SpringPolyline> BuiltInBender::springs() const
  {
    std::vector<SpringPolyline> lines;
    const double spacing = 0.5 * (length - 2 * wall) / cells_along_length;
    const double y_fabric = wall / 2;
    // Fabric: a grid in the bottom wall's mid-plane, lines along x and z.
    const unsigned int n_z_lines = 5;
    for (unsigned int k = 0; k < n_z_lines; ++k)
      {
        const double z = wall / 2 + (width - wall) * k / (n_z_lines - 1);
        SpringPolyline line{"fabric", {}, false};
        sample_segment(Point<3>(0, y_fabric, z), Point<3>(length, y_fabric, z), spacing, line.points);
        line.points.push_back(Point<3>(length, y_fabric, z));
        lines.push_back(line);
      }
    // Threads: rectangular rings in the walls' mid-surfaces, every pitch.
    const double y0 = wall / 2, y1 = height - wall / 2, z0 = wall / 2, z1 = width - wall / 2;
    for (double x = thread_pitch; x < length - wall; x += thread_pitch)
      {
        SpringPolyline ring{"thread", {}, true};
        sample_segment(Point<3>(x, y0, z0), Point<3>(x, y0, z1), spacing, ring.points);
        sample_segment(Point<3>(x, y0, z1), Point<3>(x, y1, z1), spacing, ring.points);
        sample_segment(Point<3>(x, y1, z1), Point<3>(x, y1, z0), spacing, ring.points);
        sample_segment(Point<3>(x, y1, z0), Point<3>(x, y0, z0), spacing, ring.points);
        lines.push_back(ring);
      }
    return lines;
  }
} // namespace softchain::fem
