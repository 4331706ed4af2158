#pragma once
// MultifrontalLDLT: K = L D L^T for a symmetric K, positive definite or not,
// by MUMPS's multifrontal factorisation (Amestoy et al., SIAM J. Matrix
// Anal. Appl. 23, 2001) on one MPI rank: BLAS-3 on dense frontal matrices,
// half the flops of an LU factorisation. Two kinds:
//   - with threshold pivoting over 1x1 and 2x2 pivots (Duff and Reid's
//     symmetric indefinite scheme, MUMPS's SYM = 2): stable for any
//     nonsingular K;
//   - without pivoting, the pivots in the ordering's sequence (SYM = 1, the
//     kind MUMPS meant for positive definite K): no pivot search and no
//     delayed pivots, 0.77x the time in the P10 sample's linear solve, and stable for a
//     positive definite K; for an indefinite one it may meet a small pivot,
//     so its user checks the solution (SerialDirectSolver).
//
// The tangent of a hyperelastic body under a follower pressure on a closed
// cavity, with springs and dead loads, is symmetric: the pressure's load
// p V(u) has a potential (the cavity's volume), and the FE assembly keeps that
// symmetry to round-off (1e-16 relative on P10). It is positive definite at a
// stable state but indefinite in the first Newton iterations of a large load
// step, past a limit point or while the finger buckles; LDL^T factorises
// both alike, where a Cholesky factorisation would have to give up and hand
// the tangent to an LU factorisation (docs/history.md).
//
// The fill-reducing ordering is MUMPS's automatic choice (ICNTL(7) = 7),
// which takes the ordering of fewest estimated flops among those Debian's
// build has (AMF, PORD, AMD, QAMD; not METIS or SCOTCH). Measured on single
// factors: the default P10 (8 mm, one layer) 2.9e8 flops by AMF (PORD
// 3.1e8), P13 5.1e8 by PORD (AMF 8.0e8), P10 with fibre sheets at 4 mm and
// two layers 1.24e10 by PORD (AMF 2.47e10: that solve's linear solves took
// 18 s instead of 26 s). The ordering and the elimination tree depend on
// the pattern alone: they are computed once, and each
// factorise() repeats only the numeric factorisation. The number of negative
// pivots is K's count of negative eigenvalues (Sylvester's law of inertia).
//
// `Real` is the precision of the factors: double, or float (MUMPS's single
// precision arithmetic, about half the time and memory of the double
// factorisation); K, b and x are passed in double either way, and a float
// solve is as accurate as the factors (its user refines it: SerialDirectSolver).
#include <dmumps_c.h>
#include <smumps_c.h>

#include <cstdint>
#include <vector>

namespace softchain::fem
{
  // MUMPS's interface for factors in `Real`.
  template <typename Real>
  struct MumpsArithmetic;
  template <>
  struct MumpsArithmetic<double>
  {
    using Instance = DMUMPS_STRUC_C;
    static void call(Instance *instance) { dmumps_c(instance); }
  };
  template <>
  struct MumpsArithmetic<float>
  {
    using Instance = SMUMPS_STRUC_C;
    static void call(Instance *instance) { smumps_c(instance); }
  };

  template <typename Real>
  class MultifrontalLDLT
  {
  public:
    // The pattern of a symmetric K in compressed rows (sorted columns, both
    // triangles stored); only the entries with column <= row are read.
    enum class Pivoting
    {
      none,     // the ordering's pivot sequence
      threshold // 1x1 and 2x2 pivots chosen for stability
    };
    MultifrontalLDLT(const std::vector<int64_t> &row_start, const std::vector<int64_t> &column,
                     Pivoting pivoting);
    ~MultifrontalLDLT();
    MultifrontalLDLT(const MultifrontalLDLT &)            = delete;
    MultifrontalLDLT &operator=(const MultifrontalLDLT &) = delete;

    // Factorises K with these values (in the pattern's order); false if K is
    // numerically singular (MUMPS's INFOG(1) = -10) or, without pivoting, if
    // MUMPS stops with any error (its pivots then need a search). Other MUMPS
    // errors throw.
    bool factorise(const std::vector<double> &value);
    // x = K^-1 b with the last factorisation.
    void solve(const double *b, double *x);
    // Negative eigenvalues of the last K factorised.
    int negative_pivots() const { return mumps.infog[11]; }

  private:
    void run(int job, const char *what);
    void check(const char *what) const; // throws on a MUMPS error

    Pivoting                                   pivoting;
    typename MumpsArithmetic<Real>::Instance   mumps;
    std::vector<int>                           row, col; // 1-based coordinates of the lower triangle
    std::vector<int64_t>                       entry;    // their places in the compressed-row values
    std::vector<Real>                          lower;    // their values, as MUMPS reads them
    std::vector<Real>                          rhs;
  };
} // namespace softchain::fem
