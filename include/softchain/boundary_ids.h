#pragma once
// Boundary ids of the FEM tier, assigned from the gmsh physical surface names
// of ARCHITECTURE.md ("Mesh conventions").
#include <deal.II/base/types.h>

namespace softchain::boundary
{
  constexpr dealii::types::boundary_id base   = 1; // clamped
  constexpr dealii::types::boundary_id cavity = 2; // follower pressure
  constexpr dealii::types::boundary_id tip    = 3; // distal face
  constexpr dealii::types::boundary_id other  = 0; // traction free
} // namespace softchain::boundary
