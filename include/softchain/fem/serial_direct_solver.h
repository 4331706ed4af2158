#pragma once
// SerialDirectSolver: K du = r by UMFPACK's multifrontal LU (BLAS-3 on dense
// frontal matrices) for a run on one MPI rank. Trilinos' KLU is a
// left-looking LU without supernodes: on the fill of a 3D Q2 mesh it is
// several times slower (docs/toolchain.md, "Linear solvers").
//
// The tangent's sparsity pattern never changes during a solve, so the work
// that depends on the pattern alone is done once (docs/results.md, "What a solve skips"):
//   - the compressed-row copy of K and, per Trilinos entry, its place in it,
//     so that refreshing the values is one pass without searches;
//   - UMFPACK's symbolic analysis (fill-reducing column ordering, frontal
//     matrix sizes), which the UMFPACK user guide (Davis, Sec. 5) allows to be
//     reused for every matrix with the same pattern.
// Each Newton iteration then repeats only the numeric factorisation (with its
// own threshold partial pivoting) and the triangular solves.
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <umfpack.h>

#include <array>
#include <vector>

namespace softchain::fem
{
  class SerialDirectSolver
  {
  public:
    // `matrix` must live on one rank; its sparsity pattern is copied.
    explicit SerialDirectSolver(const dealii::TrilinosWrappers::SparseMatrix &matrix);
    ~SerialDirectSolver();
    SerialDirectSolver(const SerialDirectSolver &)            = delete;
    SerialDirectSolver &operator=(const SerialDirectSolver &) = delete;

    // Factorises `matrix` (same pattern as at construction) and solves.
    void solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
               dealii::TrilinosWrappers::MPI::Vector        &solution,
               const dealii::TrilinosWrappers::MPI::Vector  &rhs);

  private:
    void copy_values(const dealii::TrilinosWrappers::SparseMatrix &matrix);
    void factorise();

    // K in compressed rows with sorted columns. UMFPACK reads compressed
    // columns, so it sees K^T and solves with UMFPACK_At.
    std::vector<SuiteSparse_long> row_start, column;
    std::vector<double>           value;
    // Entry k of the Trilinos matrix's local storage (rows in order) sits at
    // value[place[k]].
    std::vector<SuiteSparse_long> place;

    std::array<double, UMFPACK_CONTROL> control;
    void                               *symbolic = nullptr;
    void                               *numeric  = nullptr;
  };
} // namespace softchain::fem
