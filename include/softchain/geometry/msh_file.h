#pragma once
// MshFile: reader of gmsh's ASCII msh 2.2 format (what meshes/*.geo produce
// with -format msh22, and what deal.II 9.4's GridIn::read_msh reads): nodes,
// first-order tetrahedra and hexahedra (cells), triangles and quadrilaterals
// (boundary facets), each with its physical tag, and the physical names.
#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace softchain::geometry
{
  struct MshElement
  {
    std::size_t              id = 0;       // element number in the file
    int                      physical = 0; // first tag
    std::vector<std::size_t> nodes;        // 0-based indices into MshFile::nodes
  };

  struct PhysicalGroup
  {
    int dimension = 0;
    int tag       = 0;
  };

  class MshFile
  {
  public:
    // Throws InputError naming the file (and the line) if it is not an ASCII
    // msh 2.x file or holds an element type other than points, lines,
    // triangles, quadrilaterals, tetrahedra and hexahedra (first order).
    static MshFile read(const std::string &path);

    std::string                          path;
    std::vector<Eigen::Vector3d>         nodes;
    std::vector<MshElement>              cells;  // 4 (tetrahedron) or 8 (hexahedron) nodes
    std::vector<MshElement>              facets; // 3 (triangle) or 4 (quadrilateral) nodes
    std::map<std::string, PhysicalGroup> groups; // by name

    bool has_group(const std::string &name, int dimension) const;
    // The facets of a named 2D group; throws InputError naming the file and
    // the group if it is missing.
    std::vector<const MshElement *> facets_of(const std::string &group) const;
  };
} // namespace softchain::geometry
