#pragma once
// SerialDirectSolver: K du = r by UMFPACK's multifrontal LU (BLAS-3 on dense
// frontal matrices) for a run on one MPI rank. Trilinos' KLU is a
// left-looking LU without supernodes: on the fill of a 3D Q2 mesh it is
// several times slower (README, "Linear solvers"). The Trilinos matrix is
// copied into a deal.II SparseMatrix whose pattern is built once.
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace softchain
{
  using namespace dealii;

  class SerialDirectSolver
  {
  public:
    // `matrix` must live on one rank; its sparsity pattern is copied.
    explicit SerialDirectSolver(const TrilinosWrappers::SparseMatrix &matrix);

    // Factorises `matrix` (same pattern as at construction) and solves.
    void solve(const TrilinosWrappers::SparseMatrix &matrix,
               TrilinosWrappers::MPI::Vector        &solution,
               const TrilinosWrappers::MPI::Vector  &rhs);

  private:
    SparsityPattern      pattern;
    SparseMatrix<double> copy;
    SparseDirectUMFPACK  umfpack;
  };
} // namespace softchain
