#pragma once
// generate_design: the entry point of the FEM tier into the geometry module.
// Reads the "Finger design" subsection of a .prm file, meshes the design with
// gmsh unless the cache holds it, writes the spring networks (fabric and
// threads of a parametric design, or the design's own spring file), and runs
// the MeshChecks on both. Throws softchain::data::InputError on bad input.
#include <softchain/geometry/finger_design.h>
#include <softchain/geometry/gmsh_mesher.h>

#include <string>

namespace softchain::geometry
{
  struct GeneratedDesign
  {
    std::string mesh_file;   // ASCII msh 2.2 with groups base, cavity, tip, silicone
    std::string spring_file; // SpringNetworkFile format
    std::string hash;        // content hash of everything that defines mesh and springs
    double      length = 0;  // m, base face to tip face
  };

  GeneratedDesign generate_design(const FingerDesign &design, const std::string &cache_dir);
  GeneratedDesign generate_design(const FingerDesign &design, GmshMesher &mesher);
} // namespace softchain::geometry
