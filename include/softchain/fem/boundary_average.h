#pragma once
// Surface averages over a boundary part, e.g. the mean tip displacement
// (1/A) int_tip u dA, the tip measure used by the benchmarks and tests.
#include <softchain/fem/finite_element_space.h>

#include <deal.II/lac/trilinos_vector.h>

namespace softchain::fem
{
  dealii::Tensor<1, 3> mean_boundary_displacement(const FiniteElementSpace            &space,
                                          const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                                          dealii::types::boundary_id                   boundary);
} // namespace softchain::fem
