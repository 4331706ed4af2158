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
// A symmetric K is first factorised without pivoting in single precision,
// and the solution refined in double by GMRES on K with those factors as
// preconditioner until its relative residual |b - K x| / |b| meets the
// caller's `relative_residual` (an inexact Newton step's forcing term), or
// 1e-12 without one (see refine()); where the refinement does not converge,
// K is factorised without pivoting in double (no pivot search, no delayed
// pivots: the P10 sample's linear solve 0.77x the time of the pivoting
// factorisation) and the solution's backward error checked; a K whose
// pivots need a search (a zero or tiny pivot in the ordering's sequence,
// possible only where K is indefinite) is then factorised with threshold
// pivoting. Each step is taken only where the one before does not meet the
// bound (docs/history.md, "LDL^T without pivoting first" and "Factors in
// single precision, Newton's error estimate").
//
// An unsymmetric K whose caller names a part N of it such that K - N is
// symmetric (Coulomb friction's slip coupling, ObstacleContact) is solved by
// flexible GMRES on K (Saad, SIAM J. Sci. Comput. 14, 1993), right
// preconditioned by the LDL^T factors of M = K - N: single precision without
// pivoting, else double with threshold pivoting. N lives on the slipping and
// sticking contact points alone, so M^-1 K = I + M^-1 N differs from the
// identity on few directions and GMRES converges in a few iterations, each a
// pair of triangular solves and a product with K: cheaper than UMFPACK's LU
// of K, which is twice an LDL^T factorisation's flops and pivots for
// stability. GMRES stops at the residual the refinement stops at (refine());
// where it does not converge in max_krylov_iterations, K is factorised by LU.
//
// The tangent's sparsity pattern never changes during a solve, so the work
// that depends on the pattern alone is done once (docs/results.md, "What a solve skips"):
//   - the compressed-row copy of K (and, if Trilinos keeps a row's columns
//     out of order, each entry's place in it), so that refreshing the values
//     is one pass without searches;
//   - each entry's mirror K_ji, for the symmetry test;
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
#include <utility>
#include <vector>

namespace softchain::fem
{
  class SerialDirectSolver
  {
  public:
    // `matrix` must live on one rank; its sparsity pattern is copied. A
    // solution refined from single factors is accepted once its relative
    // residual is at most `relative_residual` (0: only at the backward
    // error bound).
    explicit SerialDirectSolver(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                                double relative_residual = 0.0);
    // The relative residual the following solves accept (0: only 1e-12 or
    // the backward error bound), e.g. each Newton step's forcing term.
    void accept_relative_residual(double eta) { relative_residual = eta; }
    ~SerialDirectSolver();
    SerialDirectSolver(const SerialDirectSolver &)            = delete;
    SerialDirectSolver &operator=(const SerialDirectSolver &) = delete;

    // Factorises `matrix` (same pattern as at construction) and solves;
    // false, leaving `solution` alone, if the matrix is numerically singular.
    // `unsymmetric_part`, if given (same pattern), is a part N of an
    // unsymmetric `matrix` K such that K - N is symmetric: GMRES solves K
    // with the factors of K - N (above).
    bool solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
               dealii::TrilinosWrappers::MPI::Vector        &solution,
               const dealii::TrilinosWrappers::MPI::Vector  &rhs,
               const dealii::TrilinosWrappers::SparseMatrix *unsymmetric_part = nullptr);
    // Solves with the factorisation of the last successful solve() (a
    // second right-hand side of the same K, e.g. volume control's
    // unit-pressure load).
    void solve_again(dealii::TrilinosWrappers::MPI::Vector       &solution,
                     const dealii::TrilinosWrappers::MPI::Vector &rhs);

    // Which factors solved last: LDL^T in single precision with iterative
    // refinement, LDL^T in double without or with pivoting, GMRES with the
    // LDL^T factors of K - N, or LU.
    enum class Factors
    {
      single,
      unpivoted,
      pivoted,
      krylov,
      lu
    };
    Factors last_factors() const { return last; }
    // Did the last solve use an LDL^T factorisation (else LU)?
    bool used_ldlt() const { return last != Factors::lu; }
    // GMRES iterations of the last solve with Factors::single or Factors::krylov.
    unsigned int krylov_iterations_taken() const { return krylov_iterations; }
    // Did the last LDL^T solve need the pivoting factorisation?
    bool used_pivoting() const { return last == Factors::pivoted; }
    // Negative eigenvalues of the last K factorised by LDL^T.
    int negative_eigenvalues() const;

  private:
    void copy_values(const dealii::TrilinosWrappers::SparseMatrix &matrix, std::vector<double> &into) const;
    template <typename Visit>
    bool visit_mirrors(const Visit &visit) const;
    bool symmetric(const std::vector<double> &values) const;
    bool factorise_lu(); // false if K is singular

    // K in compressed rows with sorted columns. UMFPACK reads compressed
    // columns, so it sees K^T and solves with UMFPACK_At.
    std::vector<SuiteSparse_long> row_start, column;
    std::vector<double>           value;
    // The values of M = K - N, GMRES's preconditioner (empty without N).
    std::vector<double>           symmetric_approximation;
    // Entry k of the Trilinos matrix's local storage (rows in order) sits at
    // value[place[k]]; empty where that is k (every row's columns in
    // increasing order, as deal.II's matrices keep them).
    std::vector<SuiteSparse_long> place;
    // Has each entry (i, j) its mirror (j, i) in the pattern? If so, the
    // pairs (k, m) of each entry k = (i, j) above the diagonal and its
    // mirror m = (j, i), for the symmetry test.
    bool                                               symmetric_pattern = false;
    std::vector<std::pair<SuiteSparse_long, SuiteSparse_long>> upper_mirrors;

    // x = K^-1 b for a symmetric K, each false where it does not apply (below).
    bool solve_single(const double *b, std::vector<double> &x);
    bool refine(const double *b, std::vector<double> &x); // GMRES with the single factors
    bool solve_double(const double *b, std::vector<double> &x);
    bool solve_unpivoted(const double *b, std::vector<double> &x);
    // Factorises M = K - N by LDL^T (single, else double with pivoting);
    // false if M is singular.
    bool factorise_approximation();
    // x = K^-1 b by GMRES preconditioned with the factors of M; false if it
    // does not converge.
    bool solve_krylov(const double *b, std::vector<double> &x);
    // x = K^-1 b by flexible GMRES with `apply_preconditioner(in, out)` on
    // the right; false if it does not converge in `max_iterations`.
    template <typename Preconditioner>
    bool fgmres(const double *b, std::vector<double> &x, unsigned int max_iterations,
                const Preconditioner &apply_preconditioner);
    // r = b - K x; returns the normwise backward error |r|_inf / (|K|_inf
    // |x|_inf + |b|_inf) of x (Rigal and Gaches, Numer. Math. 1967).
    double residual(const double *b, const std::vector<double> &x, std::vector<double> &r) const;
    // The backward error every solve of a symmetric K meets (solve_unpivoted(),
    // refine()).
    static constexpr double       backward_error_bound = 1e-12;
    // The refinement's budget: on P10 with fibre sheets GMRES took 3-9
    // iterations to 1e-8 |b|, so a refinement fails only where the single
    // factors are far from K. An iteration costs about 25 ms there against
    // 0.19 s for the single factorisation, so a failed refinement costs
    // about two factorisations, once per solver (after it the double
    // factors serve).
    static constexpr unsigned int max_refinement_iterations = 12;
    // GMRES's budget (one Krylov basis, no restart): on P10 pressed with
    // friction it took 4.6 iterations on average and 13 at most.
    static constexpr unsigned int max_krylov_iterations = 40;
    double                        relative_residual;

    std::unique_ptr<MultifrontalLDLT<float>>  single;           // each made when first needed
    std::unique_ptr<MultifrontalLDLT<double>> unpivoted, pivoted;
    Factors                                   last             = Factors::lu;
    unsigned int                              krylov_iterations = 0;
    // Which factors hold M for GMRES: the single ones, else `pivoted`.
    bool approximation_in_single = true;
    // False once a refinement failed (solve_single()).
    bool single_pays = true;

    std::array<double, UMFPACK_CONTROL> control;
    void                               *symbolic = nullptr;
    void                               *numeric  = nullptr;
  };
} // namespace softchain::fem
