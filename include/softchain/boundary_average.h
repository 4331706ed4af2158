#pragma once
// Surface averages over a boundary part, e.g. the mean tip displacement
// (1/A) int_tip u dA, the tip measure used by the benchmarks and tests.
#include <softchain/finite_element_space.h>

#include <deal.II/lac/trilinos_vector.h>

namespace softchain
{
  Tensor<1, 3> mean_boundary_displacement(const FiniteElementSpace            &space,
                                          const TrilinosWrappers::MPI::Vector &ghosted_u,
                                          types::boundary_id                   boundary);
} // namespace softchain
