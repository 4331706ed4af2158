#pragma once
// The area-weighted centroid of a database mesh's clamped base face: the
// point the FEM takes its base moment about (BaseReaction), where the chain
// tier measures its base wrench, and the start of the finger's base-tip
// chord (the sweep's 'chord F' samples).
#include <softchain/data/actuation_database.h>

#include <Eigen/Core>

namespace softchain::data
{
  // Over the cell faces whose corners are all base nodes (flat faces, split
  // into triangles from a corner). InputError if the mesh has no base face.
  Eigen::Vector3d base_face_centroid(const MeshRecord &mesh);
} // namespace softchain::data
