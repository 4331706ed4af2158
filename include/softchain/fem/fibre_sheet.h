#pragma once
// FibreSheet: springs homogenised over a planar convex polygon in reference
// coordinates: per fibre family a direction in the plane and the spacing of
// the fibres it stands for (geometry::FibreSheet, in the FEM's types).
// EmbeddedSpringNetwork gives each family the membrane stiffness EA / spacing.
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace softchain::fem
{
  struct FibreSheet
  {
    struct Family
    {
      dealii::Tensor<1, 3> direction; // unit
      double               spacing;   // m
    };
    std::string                   network; // e.g. "fabric", "thread"
    std::vector<dealii::Point<3>> corners;
    std::vector<Family>           families;
  };
} // namespace softchain::fem
