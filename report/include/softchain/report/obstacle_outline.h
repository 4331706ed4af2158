#pragma once
// ObstacleOutline: an obstacle of a contact sample (data::ObstacleRecord) as
// a few flat polygons for the report's pictures (SvgFingerRenderer's
// backdrop), cut to the region of the finger: a plane as the rectangle of
// it under the finger's box, a cylinder as its two end discs and the quads
// between them over the finger's width, a sphere as a disc facing the
// viewer, a box as its six faces, an stl as its triangles. The obstacle is
// placed at the end of its motion (turn and translation), where the sample
// holds it.
#include <softchain/data/obstacle_record.h>
#include <softchain/report/oblique_view.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace softchain::report
{
  using Outline = std::vector<Eigen::Vector3d>;

  // `around`: the finger's box; `view`: for the sphere's silhouette.
  std::vector<Outline> obstacle_outline(const data::ObstacleRecord &obstacle,
                                        const Eigen::AlignedBox3d  &around,
                                        const ObliqueView          &view = ObliqueView());
} // namespace softchain::report
