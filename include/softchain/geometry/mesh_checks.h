#pragma once
// MeshChecks: what must hold before a mesh is solved. Each check throws
// softchain::data::InputError naming the file and what is wrong.
#include <softchain/geometry/msh_file.h>
#include <softchain/geometry/spring_network.h>

namespace softchain::geometry
{
  class MeshChecks
  {
  public:
    // Surfaces base, cavity, tip and volume silicone exist.
    static void require_groups(const MshFile &mesh);
    // No cell is inverted or degenerate (each tetrahedron of each cell has a
    // volume above 1e-6 times its longest edge cubed).
    static void check_cells(const MshFile &mesh);
    // The cavity surface is closed: its area vectors sum to less than 1e-9
    // times its total area.
    static void check_cavity_closed(const MshFile &mesh);
    // Every spring node lies in a cell of the mesh.
    static void check_springs_inside(const MshFile &mesh, const std::vector<SpringNetwork> &networks,
                                     const std::string &spring_source);
    // All of the above.
    static void check_all(const MshFile &mesh, const std::vector<SpringNetwork> &networks,
                          const std::string &spring_source);
  };
} // namespace softchain::geometry
