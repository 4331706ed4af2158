#pragma once
// The design hash that keys a database and its samples: everything that
// changes a sample's solution -- the parsed values of the .prm subsections
// that define the design (data/prm_subsections.h: Mesh, Materials, Springs,
// Solver; numbers in canonical form, so re-formatting 2.6e5 as 260000 keeps
// the hash), plus the mesh (vertices, cells, material and boundary ids) and
// the spring polylines, which may come from files the .prm only names or
// from the Finger design that generated them. The loads are not in it: they
// are each sample's own part of its id.
#include <softchain/fem/finger_mesh.h>
#include <softchain/fem/parameters.h>

#include <string>

namespace softchain::fem
{
  std::string design_hash(const Parameters &prm, const FingerMesh &mesh);
} // namespace softchain::fem
