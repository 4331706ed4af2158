#pragma once
// The design hash that keys a database and its samples: everything that
// changes a sample's solution -- the .prm text without the subsections that
// do not (Design: name and output directory; Loads, Samples, Output,
// Reduction, Chain; comments and blank lines dropped), plus the generated mesh (vertices, cells, material and boundary
// ids) and the spring polylines, which may come from files the .prm only
// names. The loads are not in it: they are each sample's own part of its id.
#include <softchain/data/prm_file.h>
#include <softchain/finger_mesh.h>

#include <string>

namespace softchain
{
  std::string design_hash(const data::PrmFile &prm, const FingerMesh &mesh);
} // namespace softchain
