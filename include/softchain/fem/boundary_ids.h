#pragma once
// Boundary ids of the FEM tier, assigned from the gmsh physical surface names
// of docs/conventions.md ("Boundary ids and mesh groups").
#include <deal.II/base/types.h>

namespace softchain::fem::boundary
{
  constexpr dealii::types::boundary_id base   = 1; // clamped
  constexpr dealii::types::boundary_id cavity = 2; // follower pressure
  constexpr dealii::types::boundary_id tip    = 3; // distal face
  constexpr dealii::types::boundary_id other  = 0; // traction free
  // Symmetry and plane-strain faces (built by tests and benchmarks with
  // deal.II's GridGenerator, not read from gmsh): one displacement
  // component fixed, u_x = 0, u_y = 0 or u_z = 0 respectively.
  constexpr dealii::types::boundary_id fixed_x = 4;
  constexpr dealii::types::boundary_id fixed_y = 5;
  constexpr dealii::types::boundary_id fixed_z = 6;
} // namespace softchain::fem::boundary
