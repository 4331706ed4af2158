#include <softchain/fem/multifrontal_ldlt.h>

#include <deal.II/base/exceptions.h>

#include <mpi.h>

#include <algorithm>
#include <string>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // MUMPS's error codes (INFOG(1)) that a larger workspace cures: the
    // delayed pivots of an indefinite K need more than the analysis
    // estimated (MUMPS user's guide, ICNTL(14)).
    bool workspace_too_small(const int status)
    {
      return status == -8 || status == -9 || status == -14 || status == -15 || status == -17 ||
             status == -20;
    }
  } // namespace

  template <typename Real>
  MultifrontalLDLT<Real>::MultifrontalLDLT(const std::vector<int64_t> &row_start,
                                           const std::vector<int64_t> &column,
                                           const Pivoting              pivoting)
    : pivoting(pivoting)
  {
    for (std::size_t i = 0; i + 1 < row_start.size(); ++i)
      for (int64_t k = row_start[i]; k < row_start[i + 1]; ++k)
        if (column[k] <= static_cast<int64_t>(i))
          {
            row.push_back(i + 1);
            col.push_back(column[k] + 1);
            entry.push_back(k);
          }
    lower.resize(entry.size());
    rhs.resize(row_start.size() - 1);

    mumps.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    mumps.par          = 1; // this rank factorises
    mumps.sym          = pivoting == Pivoting::threshold ? 2 : 1;
    run(-1, "initialisation");
    mumps.icntl[0] = -1; // no messages: an indefinite K is an expected outcome
    mumps.icntl[1] = -1;
    mumps.icntl[2] = -1;
    mumps.icntl[3] = 0;
    mumps.icntl[6] = 7; // MUMPS chooses the ordering (header)
    mumps.n        = rhs.size();
    mumps.nnz      = entry.size();
    mumps.irn      = row.data();
    mumps.jcn      = col.data();
    mumps.a        = lower.data();
    run(1, "analysis");
  }

  template <typename Real>
  MultifrontalLDLT<Real>::~MultifrontalLDLT()
  {
    mumps.job = -2;
    MumpsArithmetic<Real>::call(&mumps);
  }

  template <typename Real>
  void MultifrontalLDLT<Real>::run(const int job, const char *what)
  {
    mumps.job = job;
    MumpsArithmetic<Real>::call(&mumps);
    check(what);
  }

  template <typename Real>
  void MultifrontalLDLT<Real>::check(const char *what) const
  {
    AssertThrow(mumps.infog[0] >= 0,
                ExcMessage(std::string("MUMPS's ") + what + " failed with INFOG(1) = " +
                           std::to_string(mumps.infog[0])));
  }

  template <typename Real>
  bool MultifrontalLDLT<Real>::factorise(const std::vector<double> &value)
  {
    for (std::size_t k = 0; k < entry.size(); ++k)
      lower[k] = value[entry[k]];
    mumps.a = lower.data();
    // Each retry doubles the extra workspace for delayed pivots (20 % by default).
    for (int attempt = 0; attempt < 4; ++attempt)
      {
        mumps.job = 2;
        MumpsArithmetic<Real>::call(&mumps);
        if (!workspace_too_small(mumps.infog[0]))
          break;
        mumps.icntl[13] = 2 * std::max(mumps.icntl[13], 20);
      }
    if (mumps.infog[0] == -10 || (pivoting == Pivoting::none && mumps.infog[0] < 0))
      return false;
    check("numeric factorisation");
    return true;
  }

  template <typename Real>
  void MultifrontalLDLT<Real>::solve(const double *b, double *x)
  {
    std::copy(b, b + rhs.size(), rhs.begin());
    mumps.rhs  = rhs.data();
    mumps.nrhs = 1;
    mumps.lrhs = rhs.size();
    run(3, "solve");
    std::copy(rhs.begin(), rhs.end(), x);
  }

  template class MultifrontalLDLT<double>;
  template class MultifrontalLDLT<float>;
} // namespace softchain::fem
