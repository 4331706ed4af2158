// Mesh generation benchmark: for each shipped design, element shape
// and resolution, the time of generate_design() with an empty cache (gmsh
// runs) and with a warm cache (read + mesh checks only), and the sizes of the
// mesh and of the spring networks, and the relative errors of the mesh's
// silicone and cavity volumes against the analytic shape, and the worst
// element shape. Prints a Markdown table.
//
//   mesh_generation [CACHE_DIR]     (default /tmp/softchain_mesh_benchmark, emptied first)
#include <softchain/geometry/cavity_surface.h>
#include <softchain/geometry/cell_geometry.h>
#include <softchain/geometry/generate_design.h>
#include <softchain/geometry/msh_file.h>
#include <softchain/geometry/spring_network_file.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace softchain::geometry;

namespace
{
  double seconds_of(GeneratedDesign &result, const FingerDesign &design, GmshMesher &mesher)
  {
    const auto start = std::chrono::steady_clock::now();
    result           = generate_design(design, mesher);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::size_t spring_nodes(const std::string &spring_file)
  {
    std::size_t n = 0;
    for (const auto &network : SpringNetworkFile::read(spring_file))
      n += network.n_nodes();
    return n;
  }

  // Worst tetrahedron (hexahedra: of their six) by 6 sqrt(2) V / (longest
  // edge)^3: 1 for a regular tetrahedron, 0 for a flat one.
  double worst_shape(const MshFile &mesh)
  {
    double worst = 1.0;
    for (const auto &cell : mesh.cells)
      for (const auto &t : CellGeometry::tetrahedra(cell))
        {
          double longest = 0.0;
          for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
              longest = std::max(longest, (mesh.nodes[t[a]] - mesh.nodes[t[b]]).norm());
          const double shape = 6.0 * std::sqrt(2.0) * CellGeometry::signed_volume(mesh.nodes, t) /
                               std::pow(longest, 3);
          worst = std::min(worst, shape);
        }
    return worst;
  }

  double relative_error(double value, double exact)
  {
    return std::abs(value - exact) / exact;
  }

  void row(const std::string &name, bool hexahedra, int resolution, const std::string &cache_dir)
  {
    FingerDesign design = FingerDesign::read(std::string(SOFTCHAIN_SOURCE_DIR) + "/parameter_files/" +
                                             name + ".prm");
    design.hexahedra  = hexahedra;
    design.resolution = resolution;
    GmshMesher      mesher(cache_dir);
    GeneratedDesign result;
    const double    cold = seconds_of(result, design, mesher);
    const double    warm = seconds_of(result, design, mesher);
    const MshFile       mesh = MshFile::read(result.mesh_file);
    const CavitySurface cavity(mesh);
    const auto         &d = design.dimensions;
    std::printf("| %-14s | %-3s | %d | %6.4f | %7zu | %6zu | %6zu | %5zu | %6.2f | %6.2f | %7.1e | "
                "%7.1e | %5.3f |\n",
                name.c_str(), hexahedra ? "hex" : "tet", resolution, design.mesh_size(),
                mesh.cells.size(), mesh.nodes.size(), cavity.triangles().size(),
                spring_nodes(result.spring_file), cold, warm,
                relative_error(CellGeometry::total_volume(mesh), d.material_volume()),
                relative_error(cavity.enclosed_volume(), d.cavity_volume()), worst_shape(mesh));
  }
} // namespace

int main(int argc, char **argv)
{
  const std::string cache_dir = argc > 1 ? argv[1] : "/tmp/softchain_mesh_benchmark";
  std::filesystem::remove_all(cache_dir);
  std::printf("| design | element | res | size (m) | cells | nodes | cavity triangles | spring nodes "
              "| cold (s) | cached (s) | silicone volume error | cavity volume error | worst tet shape |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const char *name : {"p10", "p13", "parallelepiped"})
    for (const bool hexahedra : {false, true})
      for (int resolution = 0; resolution <= 2; ++resolution)
        row(name, hexahedra, resolution, cache_dir);
  return 0;
}
