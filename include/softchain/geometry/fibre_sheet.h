#pragma once
// FibreSheet: a passive structure smeared over a surface. Where the paper
// (Sec. III-A) places 1D springs a spacing s apart, a sheet carries the same
// fibres homogenised: per unit width a membrane stiffness EA / s along each
// fibre family. A line of springs in a 3D solid has no mesh-converged
// stiffness (the solid around a line load deforms without bound as the mesh
// refines, docs/fem_accuracy.md), a sheet has one.
//
// The sheet is a planar convex polygon in reference coordinates (m); each
// family's direction lies in its plane.
#include <Eigen/Core>

#include <vector>

namespace softchain::geometry
{
  struct FibreSheet
  {
    struct Family
    {
      Eigen::Vector3d direction; // unit, in the sheet's plane
      double          spacing;   // m between the fibres it homogenises
    };
    std::vector<Eigen::Vector3d> corners;
    std::vector<Family>          families;
  };
} // namespace softchain::geometry
