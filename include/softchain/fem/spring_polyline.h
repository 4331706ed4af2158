#pragma once
// SpringPolyline: a chain of 1D tension-only springs given by its nodes in
// reference coordinates (the paper's passive structures: fabric and threads).
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  struct SpringPolyline
  {
    std::string                   network; // e.g. "fabric", "thread"
    std::vector<dealii::Point<3>> points;
    bool                          closed = false; // last node linked to the first
  };
} // namespace softchain::fem
