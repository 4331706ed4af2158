#pragma once
// SpringNetwork: one passive structure of the paper (Sec. III-A), a set of
// polylines of tension-only springs given by their nodes in reference
// coordinates (m). Each node lies inside the body material and moves with the
// cell that contains it. Names used: "fabric" (strain-limiting layer) and
// "thread" (cross-sectional rings). A network may instead, or as well, hold
// its fibres smeared over sheets (FibreSheet).
#include <softchain/geometry/fibre_sheet.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace softchain::geometry
{
  struct SpringNetwork
  {
    struct Polyline
    {
      bool                         closed = false; // last node linked to the first
      std::vector<Eigen::Vector3d> points;
    };

    std::string           name;
    std::vector<Polyline>   polylines;
    std::vector<FibreSheet> sheets;

    std::size_t n_nodes() const;
  };
} // namespace softchain::geometry
