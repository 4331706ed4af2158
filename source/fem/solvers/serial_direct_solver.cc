#include <softchain/fem/serial_direct_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    void check(SuiteSparse_long status, const std::string &step)
    {
      AssertThrow(status == UMFPACK_OK,
                  ExcMessage("UMFPACK " + step + " failed with status " + std::to_string(status)));
    }

    // A linear operator y = A x on deal.II vectors, for deal.II's solvers.
    template <typename Apply>
    struct LinearMap
    {
      Apply apply; // apply(x, y) writes y = A x
      void  vmult(Vector<double> &y, const Vector<double> &x) const { apply(x.begin(), y.begin()); }
    };
    template <typename Apply>
    LinearMap<Apply> linear_map(Apply apply)
    {
      return {apply};
    }
  } // namespace

  SerialDirectSolver::SerialDirectSolver(const TrilinosWrappers::SparseMatrix &matrix,
                                         const double                          relative_residual)
    : relative_residual(relative_residual)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()) == 1,
                ExcMessage("SerialDirectSolver runs on one MPI rank only"));
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    // The global index of each local column, looked up once.
    std::vector<SuiteSparse_long> global(epetra.ColMap().NumMyElements());
    for (std::size_t c = 0; c < global.size(); ++c)
      global[c] = epetra.ColMap().GID64(c);
    row_start.reserve(epetra.NumMyRows() + 1);
    row_start.assign(1, 0);
    column.resize(epetra.NumMyNonzeros());
    std::vector<int> order;
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        int  n;
        int *local_columns;
        epetra.Graph().ExtractMyRowView(row, n, local_columns);
        // This row's entries in increasing global column: Epetra keeps them
        // in increasing local column, the same order where the column map
        // is increasing (deal.II's is), else they are sorted here.
        const SuiteSparse_long first = row_start.back();
        const bool             sorted = std::is_sorted(local_columns, local_columns + n,
                                                       [&](int a, int b) { return global[a] < global[b]; });
        if (!sorted && place.empty())
          {
            place.resize(column.size());
            std::iota(place.begin(), place.begin() + first, 0);
          }
        order.resize(n);
        std::iota(order.begin(), order.end(), 0);
        if (!sorted)
          std::sort(order.begin(), order.end(),
                    [&](int a, int b) { return global[local_columns[a]] < global[local_columns[b]]; });
        for (int k = 0; k < n; ++k)
          {
            column[first + k] = global[local_columns[order[k]]];
            if (!place.empty())
              place[first + order[k]] = first + k;
          }
        row_start.push_back(first + n);
      }
    value.resize(column.size());
    umfpack_dl_defaults(control.data());
    symmetric_pattern = visit_mirrors([&](const SuiteSparse_long k, const SuiteSparse_long m) {
      if (k < m) // rows in order: (i, j) comes before (j, i) where i < j
        upper_mirrors.emplace_back(k, m);
    });
    if (!symmetric_pattern)
      upper_mirrors.clear();
  }

  // Calls visit(k, m) for every entry k = (i, j) and its mirror m = (j, i);
  // false (and stops) if the pattern is not symmetric. Rows are visited in
  // increasing i, so the entries (j, i) of each row j come in the order of
  // its sorted columns: a cursor per row finds each mirror, in one pass
  // without searches.
  template <typename Visit>
  bool SerialDirectSolver::visit_mirrors(const Visit &visit) const
  {
    std::vector<SuiteSparse_long> next(row_start.begin(), row_start.end() - 1);
    for (std::size_t i = 0; i + 1 < row_start.size(); ++i)
      for (SuiteSparse_long k = row_start[i]; k < row_start[i + 1]; ++k)
        {
          const SuiteSparse_long j = column[k];
          if (next[j] == row_start[j + 1] || column[next[j]] != static_cast<SuiteSparse_long>(i))
            return false;
          visit(k, next[j]++);
        }
    return true;
  }

  bool SerialDirectSolver::symmetric(const std::vector<double> &values) const
  {
    if (!symmetric_pattern)
      return false;
    double largest = 0.0, asymmetry = 0.0;
    for (const double v : values)
      largest = std::max(largest, std::abs(v));
    for (const auto &[k, m] : upper_mirrors)
      asymmetry = std::max(asymmetry, std::abs(values[k] - values[m]));
    return asymmetry <= 1e-12 * largest;
  }

  SerialDirectSolver::~SerialDirectSolver()
  {
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    if (symbolic)
      umfpack_dl_free_symbolic(&symbolic);
  }

  void SerialDirectSolver::copy_values(const TrilinosWrappers::SparseMatrix &matrix,
                                       std::vector<double>                  &into) const
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    AssertThrow(static_cast<std::size_t>(epetra.NumMyNonzeros()) == column.size(),
                ExcMessage("SerialDirectSolver: a matrix of another sparsity pattern"));
    into.resize(column.size());
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        int     n;
        double *values;
        epetra.ExtractMyRowView(row, n, values);
        if (place.empty())
          std::copy(values, values + n, into.begin() + row_start[row]);
        else
          for (int k = 0; k < n; ++k)
            into[place[row_start[row] + k]] = values[k];
      }
  }

  // The symbolic analysis once, the numeric factorisation every call.
  bool SerialDirectSolver::factorise_lu()
  {
    const SuiteSparse_long n = row_start.size() - 1;
    if (!symbolic)
      check(umfpack_dl_symbolic(n, n, row_start.data(), column.data(), value.data(), &symbolic,
                                control.data(), nullptr),
            "symbolic analysis");
    if (numeric)
      umfpack_dl_free_numeric(&numeric);
    const SuiteSparse_long status = umfpack_dl_numeric(row_start.data(), column.data(), value.data(),
                                                       symbolic, &numeric, control.data(), nullptr);
    if (status == UMFPACK_WARNING_singular_matrix)
      return false;
    check(status, "numeric factorisation");
    return true;
  }

  bool SerialDirectSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                                 TrilinosWrappers::MPI::Vector        &solution,
                                 const TrilinosWrappers::MPI::Vector  &rhs,
                                 const TrilinosWrappers::SparseMatrix *unsymmetric_part)
  {
    copy_values(matrix, value);
    if (!symmetric(value))
      {
        if (unsymmetric_part)
          {
            copy_values(*unsymmetric_part, symmetric_approximation);
            for (std::size_t k = 0; k < value.size(); ++k)
              symmetric_approximation[k] = value[k] - symmetric_approximation[k];
            std::vector<double> x(rhs.locally_owned_size());
            if (symmetric(symmetric_approximation) && factorise_approximation() &&
                solve_krylov(rhs.begin(), x))
              {
                last = Factors::krylov;
                std::copy(x.begin(), x.end(), solution.begin());
                return true;
              }
          }
        last = Factors::lu;
        if (!factorise_lu())
          return false;
        solve_again(solution, rhs);
        return true;
      }
    std::vector<double> x(rhs.locally_owned_size());
    if (!solve_single(rhs.begin(), x) && !solve_double(rhs.begin(), x))
      return false;
    std::copy(x.begin(), x.end(), solution.begin());
    return true;
  }

  // The double factors: without pivoting if that solve is backward stable,
  // else with threshold pivoting; false if K is singular.
  bool SerialDirectSolver::solve_double(const double *b, std::vector<double> &x)
  {
    if (solve_unpivoted(b, x))
      {
        last = Factors::unpivoted;
        return true;
      }
    if (!pivoted)
      pivoted = std::make_unique<MultifrontalLDLT<double>>(row_start, column,
                                                           MultifrontalLDLT<double>::Pivoting::threshold);
    last = Factors::pivoted;
    if (!pivoted->factorise(value))
      return false;
    pivoted->solve(b, x.data());
    return true;
  }

  int SerialDirectSolver::negative_eigenvalues() const
  {
    switch (last)
      {
        case Factors::single:
          return single->negative_pivots();
        case Factors::unpivoted:
          return unpivoted->negative_pivots();
        case Factors::pivoted:
          return pivoted->negative_pivots();
        default:
          return 0;
      }
  }

  // Single factors serve while they pay: a refinement that does not
  // converge in its budget (below) hands this and every later K to the
  // double factors.
  bool SerialDirectSolver::solve_single(const double *b, std::vector<double> &x)
  {
    if (!single_pays)
      return false;
    if (!single)
      single = std::make_unique<MultifrontalLDLT<float>>(row_start, column,
                                                         MultifrontalLDLT<float>::Pivoting::none);
    single_pays = single->factorise(value) && refine(b, x);
    if (single_pays)
      last = Factors::single;
    return single_pays;
  }

  // Iterative refinement with factors in single precision, by GMRES
  // (Carson and Higham, SIAM J. Sci. Comput. 39, 2017, "GMRES-IR"): flexible
  // GMRES on K in double, right preconditioned by the single factors
  // (L D L^T)_single^-1. Wilkinson's stationary refinement, x_{k+1} = x_k +
  // (L D L^T)_single^-1 (b - K x_k), gains -log10(cond(K) u_single) digits a
  // step (u_single = 6e-8) and stalls once cond(K) u_single nears 1; GMRES
  // on the preconditioned K, whose eigenvalues cluster at 1 within about
  // cond(K) u_single, converges there too. On P10 with fibre sheets (Q2, 4 mm,
  // 36,750 DoFs) the stationary refinement gained 0.6-0.9 digits a step, gave
  // up after six and handed every later K to double factors (0.3 s a
  // factorisation against 0.19 s in single); GMRES reached the same residual
  // in 3-9 iterations, each a pair of triangular solves (15 ms) and a product
  // with K.
  //
  // The solution is accepted at the caller's relative residual |b - K x| <=
  // `relative_residual` |b|, or at 1e-12 |b| without one (at least as strict
  // as the double factors' backward error bound, solve_unpivoted()). A Newton
  // step needs no more: with a relative linear residual eta it converges as
  // Newton's up to a term eta |R| (Dembo, Eisenstat and Steihaug, SIAM J.
  // Numer. Anal. 19, 1982).
  bool SerialDirectSolver::refine(const double *b, std::vector<double> &x)
  {
    return fgmres(b, x, max_refinement_iterations,
                  [this](const double *in, double *out) { single->solve(in, out); });
  }

  bool SerialDirectSolver::factorise_approximation()
  {
    if (!single)
      single = std::make_unique<MultifrontalLDLT<float>>(row_start, column,
                                                         MultifrontalLDLT<float>::Pivoting::none);
    approximation_in_single = single->factorise(symmetric_approximation);
    if (approximation_in_single)
      return true;
    if (!pivoted)
      pivoted = std::make_unique<MultifrontalLDLT<double>>(row_start, column,
                                                           MultifrontalLDLT<double>::Pivoting::threshold);
    return pivoted->factorise(symmetric_approximation);
  }

  // GMRES on K with the factors of M = K - N: single precision without
  // pivoting, else double with threshold pivoting (factorise_approximation()).
  bool SerialDirectSolver::solve_krylov(const double *b, std::vector<double> &x)
  {
    return fgmres(b, x, max_krylov_iterations, [this](const double *in, double *out) {
      if (approximation_in_single)
        single->solve(in, out);
      else
        pivoted->solve(in, out);
    });
  }

  // Flexible GMRES: right preconditioning with factors in single precision
  // is a linear map only up to their round-off, which FGMRES's kept
  // preconditioned vectors absorb. A solution is accepted where its true
  // residual meets |b - K x| <= eta |b|, eta the caller's relative residual
  // (refine()) or 1e-12 without one, or where its backward error meets the
  // double factors' bound (solve_unpivoted(); the only test an
  // ill-conditioned K can meet, whose solutions are large). Where the
  // preconditioned K is ill conditioned, the residual GMRES estimates from
  // its basis drifts from the true one (Hilbert matrix of order 8: 1e-12
  // against 2e-10), so GMRES is restarted on the true residual, the outer
  // loop of iterative refinement (Carson and Higham, above), until the
  // budget of `max_iterations` is spent.
  template <typename Preconditioner>
  bool SerialDirectSolver::fgmres(const double *b, std::vector<double> &x, const unsigned int max_iterations,
                                  const Preconditioner &apply_preconditioner)
  {
    const std::size_t n = x.size();
    const auto        product = linear_map([this](const double *in, double *out) {
      for (std::size_t i = 0; i + 1 < row_start.size(); ++i)
        {
          double sum = 0;
          for (SuiteSparse_long k = row_start[i]; k < row_start[i + 1]; ++k)
            sum += value[k] * in[column[k]];
          out[i] = sum;
        }
    });
    const auto          preconditioner = linear_map(apply_preconditioner);
    Vector<double>      residual_vector(b, b + n), correction(n);
    std::vector<double> r(b, b + n);
    const double        eta    = relative_residual > 0 ? relative_residual : backward_error_bound;
    const double        target = eta * residual_vector.l2_norm();
    std::fill(x.begin(), x.end(), 0.0);
    krylov_iterations = 0;
    while (krylov_iterations < max_iterations)
      {
        SolverControl control(max_iterations - krylov_iterations, target, false, false);
        SolverFGMRES<Vector<double>> gmres(control, SolverFGMRES<Vector<double>>::AdditionalData(max_iterations));
        std::copy(r.begin(), r.end(), residual_vector.begin());
        correction = 0;
        try
          {
            gmres.solve(product, correction, residual_vector, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // The budget is spent; the last iterate may still pass below.
          }
        krylov_iterations += std::max(1u, control.last_step());
        for (std::size_t i = 0; i < n; ++i)
          x[i] += correction[i];
        const double error = residual(b, x, r);
        if (error <= backward_error_bound ||
            std::sqrt(std::inner_product(r.begin(), r.end(), r.begin(), 0.0)) <= target)
          return true;
      }
    return false;
  }

  // Without pivoting the factorisation is as stable as its pivots allow: a
  // small pivot of an indefinite K shows in the solution's backward error.
  // A backward-stable solve has one of the order of the unit round-off times
  // a modest growth factor (at most 2.1e-14 over the demo's 900 solves, 1e-16
  // on the CalculiX bender's Q2 tangents, indefinite ones included); above
  // 1e-12 the pivoting factorisation solves instead (a dense random K with a
  // diagonal of 1e-9 gave 1e-8). A backward error below 1e-12 is far below
  // what Newton's quadratic convergence needs of its update: with beta the
  // backward error, the update's linear residual is |K du + R| <= beta (|K|
  // |du| + |R|) <= beta (1 + cond(K)) |R|, 1e-4 |R| even for cond(K) = 1e8,
  // and an inexact Newton step with a relative linear residual eta
  // converges as Newton's up to a term eta |R| (Dembo, Eisenstat and
  // Steihaug, SIAM J. Numer. Anal. 19, 1982), below the residual tolerance.
  bool SerialDirectSolver::solve_unpivoted(const double *b, std::vector<double> &x)
  {
    if (!unpivoted)
      unpivoted = std::make_unique<MultifrontalLDLT<double>>(row_start, column,
                                                             MultifrontalLDLT<double>::Pivoting::none);
    if (!unpivoted->factorise(value))
      return false;
    unpivoted->solve(b, x.data());
    std::vector<double> r(x.size());
    return residual(b, x, r) <= backward_error_bound;
  }

  double SerialDirectSolver::residual(const double *b, const std::vector<double> &x,
                                      std::vector<double> &r) const
  {
    double largest = 0, k_norm = 0, x_norm = 0, b_norm = 0;
    for (std::size_t i = 0; i + 1 < row_start.size(); ++i)
      {
        double kx = 0, row_sum = 0;
        for (SuiteSparse_long k = row_start[i]; k < row_start[i + 1]; ++k)
          {
            kx += value[k] * x[column[k]];
            row_sum += std::abs(value[k]);
          }
        r[i]    = b[i] - kx;
        largest = std::max(largest, std::abs(r[i]));
        k_norm  = std::max(k_norm, row_sum);
        x_norm  = std::max(x_norm, std::abs(x[i]));
        b_norm  = std::max(b_norm, std::abs(b[i]));
      }
    return largest / (k_norm * x_norm + b_norm);
  }

  // On one rank the vectors' local arrays hold every entry in order.
  void SerialDirectSolver::solve_again(TrilinosWrappers::MPI::Vector       &solution,
                                       const TrilinosWrappers::MPI::Vector &rhs)
  {
    switch (last)
      {
        case Factors::single:
          {
            // A right-hand side the refinement does not converge for is
            // solved with double factors of the same K.
            std::vector<double> x(rhs.locally_owned_size());
            AssertThrow(refine(rhs.begin(), x) || solve_double(rhs.begin(), x),
                        ExcMessage("a tangent factorised in single precision is singular in double"));
            std::copy(x.begin(), x.end(), solution.begin());
            break;
          }
        case Factors::unpivoted:
          unpivoted->solve(rhs.begin(), solution.begin());
          break;
        case Factors::pivoted:
          pivoted->solve(rhs.begin(), solution.begin());
          break;
        case Factors::krylov:
          {
            std::vector<double> x(rhs.locally_owned_size());
            if (solve_krylov(rhs.begin(), x))
              {
                std::copy(x.begin(), x.end(), solution.begin());
                break;
              }
            // GMRES did not converge for this right-hand side: LU of the same K.
            AssertThrow(factorise_lu(), ExcMessage("a tangent solved by GMRES is singular"));
            last = Factors::lu;
          }
          [[fallthrough]];
        case Factors::lu:
          check(umfpack_dl_solve(UMFPACK_At, row_start.data(), column.data(), value.data(),
                                 solution.begin(), rhs.begin(), numeric, control.data(), nullptr),
                "solve");
          break;
      }
  }
} // namespace softchain::fem
