#pragma once
// SerialDirectSolver: K du = r on one MPI rank, by MUMPS's multifrontal
// LDL^T factorisation where K is symmetric (MultifrontalLDLT, positive
// definite or indefinite), otherwise by UMFPACK's multifrontal LU (BLAS-3 on
// dense frontal matrices). Trilinos' KLU is a left-looking LU without
// supernodes: on the fill of a 3D Q2 mesh it is several times slower
// (docs/toolchain.md, "Linear solvers").
//
// K is symmetric when every load has a potential (a follower pressure on a
// closed cavity, dead loads, springs); a cavity cut open by a symmetry plane
// makes it unsymmetric. Each solve checks the values against their mirror
// entries, |K_ij - K_ji| <= 1e-12 max|K| (round-off of the assembly: 1e-16
// relative on P10), and factorises a symmetric K by LDL^T, an unsymmetric
// one by LU.
//
// A symmetric K is first factorised without pivoting (no pivot search, no
// delayed pivots: the P10 sample's linear solve 0.77x the time of the
// pivoting factorisation), and the solution's normwise backward error is
// checked; a K whose pivots need a search (a zero or tiny pivot in the
// ordering's sequence, possible only where K is indefinite) is then
// factorised with threshold pivoting. On the demo's 900 Newton solves none
// needed it (docs/results.md, "LDL^T without pivoting first").
//
// The tangent's sparsity pattern never changes during a solve, so the work
// that depends on the pattern alone is done once (docs/results.md, "What a solve skips"):
//   - the compressed-row copy of K and, per Trilinos entry, its place in it,
//     so that refreshing the values is one pass without searches;
//   - each entry's mirror K_ji, for the symmetry check;
//   - MUMPS's and UMFPACK's symbolic analyses (fill-reducing orderings,
//     elimination trees and frontal matrix sizes), which their user guides
//     allow to be reused for every matrix with the same pattern; each is made
//     when first needed.
// Each Newton iteration then repeats only a numeric factorisation and the
// triangular solves.
#include <softchain/fem/multifrontal_ldlt.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <umfpack.h>

#include <array>
#include <memory>
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

    // Factorises `matrix` (same pattern as at construction) and solves;
    // false, leaving `solution` alone, if the matrix is numerically singular.
    bool solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
               dealii::TrilinosWrappers::MPI::Vector        &solution,
               const dealii::TrilinosWrappers::MPI::Vector  &rhs);
    // Solves with the factorisation of the last successful solve() (a
    // second right-hand side of the same K, e.g. volume control's
    // unit-pressure load).
    void solve_again(dealii::TrilinosWrappers::MPI::Vector       &solution,
                     const dealii::TrilinosWrappers::MPI::Vector &rhs);

    // Did the last solve use the LDL^T factorisation (else LU)?
    bool used_ldlt() const { return last_was_ldlt; }
    // Negative eigenvalues of the last K factorised by LDL^T.
    int negative_eigenvalues() const { return last_ldlt ? last_ldlt->negative_pivots() : 0; }
    // Did the last LDL^T solve need the pivoting factorisation?
    bool used_pivoting() const { return last_ldlt && last_ldlt == pivoted.get(); }

  private:
    void copy_values(const dealii::TrilinosWrappers::SparseMatrix &matrix);
    void find_mirrors();
    bool symmetric() const;
    bool factorise_lu(); // false if K is singular

    // K in compressed rows with sorted columns. UMFPACK reads compressed
    // columns, so it sees K^T and solves with UMFPACK_At.
    std::vector<SuiteSparse_long> row_start, column;
    std::vector<double>           value;
    // Entry k of the Trilinos matrix's local storage (rows in order) sits at
    // value[place[k]].
    std::vector<SuiteSparse_long> place;
    // value[mirror[k]] is K_ji for value[k] = K_ij; empty if the pattern is
    // not symmetric.
    std::vector<SuiteSparse_long> mirror;

    // x = K^-1 b by the LDL^T factorisation without pivoting, if its normwise
    // backward error is small enough (below); false otherwise.
    bool solve_unpivoted(const dealii::TrilinosWrappers::MPI::Vector &rhs, std::vector<double> &x);
    // The normwise backward error |b - K x|_inf / (|K|_inf |x|_inf + |b|_inf)
    // of x for K x = b (Rigal and Gaches, Numer. Math. 1967).
    double backward_error(const double *b, const std::vector<double> &x) const;

    std::unique_ptr<MultifrontalLDLT> unpivoted, pivoted; // each made when first needed
    MultifrontalLDLT                 *last_ldlt     = nullptr;
    bool                              last_was_ldlt = false;

    std::array<double, UMFPACK_CONTROL> control;
    void                               *symbolic = nullptr;
    void                               *numeric  = nullptr;
  };
} // namespace softchain::fem
