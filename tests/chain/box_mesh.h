#pragma once
// Structured meshes of a finger-like box [0, L] x [y0, y0 + h] x [-w/2, w/2]
// with an optional rectangular cavity (a hollow section of wall thickness d),
// as hexahedra (deal.II lexicographic corners) or each hexahedron split into
// the 6 tetrahedra around its main diagonal.
#include <softchain/data/actuation_database.h>

#include <array>

namespace softchain::chain::testing
{
  struct BoxMeshSpec
  {
    double length = 0.09, height = 0.012, width = 0.016, y0 = -0.002;
    int    nx = 18, ny = 6, nz = 8;
    int    wall_cells = 0; // > 0: hollow, walls this many cells thick
    bool   tetrahedra = false;
  };

  inline data::MeshRecord box_mesh(const BoxMeshSpec &s)
  {
    data::MeshRecord mesh;
    const auto node = [&](int i, int j, int k) {
      return static_cast<std::int64_t>(i + (s.nx + 1) * (j + (s.ny + 1) * k));
    };
    for (int k = 0; k <= s.nz; ++k)
      for (int j = 0; j <= s.ny; ++j)
        for (int i = 0; i <= s.nx; ++i)
          mesh.X.push_back({s.length * i / s.nx, s.y0 + s.height * j / s.ny,
                            s.width * (double(k) / s.nz - 0.5)});
    const auto in_cavity = [&](int j, int k) {
      const int d = s.wall_cells;
      return d > 0 && j >= d && j < s.ny - d && k >= d && k < s.nz - d;
    };
    static constexpr std::array<std::array<int, 4>, 6> kuhn = {
      {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};
    mesh.nodes_per_cell = s.tetrahedra ? 4 : 8;
    for (int k = 0; k < s.nz; ++k)
      for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i)
          {
            if (in_cavity(j, k))
              continue;
            std::array<std::int64_t, 8> hex;
            for (int v = 0; v < 8; ++v)
              hex[v] = node(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1));
            if (!s.tetrahedra)
              mesh.cells.insert(mesh.cells.end(), hex.begin(), hex.end());
            else
              for (const auto &tet : kuhn)
                for (const int v : tet)
                  mesh.cells.push_back(hex[v]);
          }
    for (int k = 0; k <= s.nz; ++k)
      for (int j = 0; j <= s.ny; ++j)
        mesh.tip_nodes.push_back(node(s.nx, j, k));
    for (int k = 0; k <= s.nz; ++k)
      for (int j = 0; j <= s.ny; ++j)
        mesh.base_nodes.push_back(node(0, j, k));
    return mesh;
  }
} // namespace softchain::chain::testing
