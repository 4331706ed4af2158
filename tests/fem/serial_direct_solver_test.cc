// SerialDirectSolver (MUMPS's LDL^T or UMFPACK's LU on a copy of the
// Trilinos matrix) solves the same system as Trilinos' KLU: the demo
// finger's tangent with springs and pressure, at two deformed states, the
// second with the symbolic analyses of the first; symmetric matrices,
// definite or indefinite, go to LDL^T, whose inertia is checked, and an
// unsymmetric one goes to LU; singular ones are reported.
#include "fem_test_tools.h"

#include <softchain/fem/serial_direct_solver.h>
#include <softchain/fem/tangent_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <sstream>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // K du = r by Trilinos' KLU, which shares no code with SerialDirectSolver.
  TrilinosWrappers::MPI::Vector klu_solution(const TrilinosWrappers::SparseMatrix &K,
                                             const TrilinosWrappers::MPI::Vector  &r)
  {
    TrilinosWrappers::MPI::Vector klu(r);
    SolverControl                 control(1, 0);
    TrilinosWrappers::SolverDirect(control, TrilinosWrappers::SolverDirect::AdditionalData(
                                              false, "Amesos_Klu"))
      .solve(K, klu, r);
    return klu;
  }

  TrilinosWrappers::MPI::Vector klu_solution(const QuasiStaticSolver &solver)
  {
    return klu_solution(solver.tangent(), solver.negative_residual());
  }

  double relative_difference(TrilinosWrappers::MPI::Vector a, const TrilinosWrappers::MPI::Vector &b)
  {
    a -= b;
    return a.l2_norm() / b.l2_norm();
  }

  // The normwise backward error |b - K x|_inf / (|K|_inf |x|_inf + |b|_inf)
  // of x for K x = b (Rigal and Gaches, 1967), by Trilinos' product.
  double backward_error(const TrilinosWrappers::SparseMatrix &K, const TrilinosWrappers::MPI::Vector &x,
                        const TrilinosWrappers::MPI::Vector &b)
  {
    TrilinosWrappers::MPI::Vector r(b);
    K.vmult(r, x);
    r -= b;
    return r.linfty_norm() / (K.linfty_norm() * x.linfty_norm() + b.linfty_norm());
  }
  // A symmetric n x n matrix on one rank, tridiagonal or full, with K_ij =
  // K_ji = entry(i, j) for i <= j (called in increasing i, then j).
  TrilinosWrappers::SparseMatrix symmetric_matrix(const unsigned int n, const bool tridiagonal,
                                                  const std::function<double(unsigned int, unsigned int)> &entry)
  {
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (!tridiagonal || (j + 1 >= i && j <= i + 1))
          pattern.add(i, j);
    const IndexSet                 all = complete_index_set(n);
    TrilinosWrappers::SparseMatrix K;
    K.reinit(all, all, pattern, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i; j < n; ++j)
        if (pattern.exists(i, j))
          {
            const double k_ij = entry(i, j);
            K.set(i, j, k_ij);
            K.set(j, i, k_ij);
          }
    K.compress(VectorOperation::insert);
    return K;
  }

  // b_i = 1 + i.
  TrilinosWrappers::MPI::Vector ramp(const unsigned int n)
  {
    TrilinosWrappers::MPI::Vector b(complete_index_set(n), MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = 1.0 + i;
    b.compress(VectorOperation::insert);
    return b;
  }
} // namespace

TEST_CASE("the one-rank direct solver and KLU give the same Newton update", "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return; // SerialDirectSolver is the one-rank path
  test::SolverFixture f(test::parameters_from_text("serial_direct", test::bender_prm("Q2", 4)));
  QuasiStaticSolver &solver = *f.solver;
  solver.set_displacement(test::smooth_displacement(solver, 2e-3, 0.05, 1));
  LoadState load;
  load.pressure = 2e4;
  REQUIRE(solver.assemble(load, true));

  TrilinosWrappers::MPI::Vector update(solver.negative_residual());
  SerialDirectSolver            direct(solver.tangent());
  REQUIRE(direct.solve(solver.tangent(), update, solver.negative_residual()));
  // The solver refines single-precision factors to a backward error of
  // 1e-12 (its contract; the test's product sums in another order, 1e-16).
  CHECK(direct.last_factors() == SerialDirectSolver::Factors::single);
  CHECK(backward_error(solver.tangent(), update, solver.negative_residual()) <= 1.01e-12);
  // KLU is backward stable: the difference is bounded by cond(K) times the
  // two backward errors. The ratio of forward to backward error on these
  // tangents was measured at 1e5 to 1e6 (1.3e-7 to 1.2e-6 for solutions
  // accepted at 1e-12; 1.6e-9 to 1.3e-8 at 1e-14); 1e-5 leaves a factor of 8.
  CHECK(relative_difference(update, klu_solution(solver)) < 1e-5);

  // A second state: new values in the same pattern. The solver keeps its
  // symbolic analyses and must still solve the new system, not the old one
  // (the two solutions differ by far more than the tolerance).
  const TrilinosWrappers::MPI::Vector first = update;
  solver.set_displacement(test::smooth_displacement(solver, 6e-3, 0.05, 2));
  load.pressure = 4e4;
  REQUIRE(solver.assemble(load, true));
  REQUIRE(direct.solve(solver.tangent(), update, solver.negative_residual()));
  CHECK(relative_difference(update, klu_solution(solver)) < 1e-5);
  CHECK(relative_difference(first, update) > 1e-3);
}

TEST_CASE("symmetric tangents are factorised by LDL^T with their inertia, others by LU",
          "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  test::SolverFixture f(test::parameters_from_text("ldlt", test::bender_prm("Q2", 4)));
  QuasiStaticSolver &solver = *f.solver;
  LoadState          load;
  load.pressure = 2e4;
  REQUIRE(solver.solve(load).converged);
  REQUIRE(solver.assemble(load, true)); // K and the (small) residual at the equilibrium
  const TrilinosWrappers::SparseMatrix &K = solver.tangent();
  const TrilinosWrappers::MPI::Vector  &r = solver.negative_residual();

  // At a stable equilibrium the closed cavity's follower pressure has a
  // potential (-p V): K is symmetric and positive definite.
  double asymmetry = 0, largest = 0;
  for (types::global_dof_index i = 0; i < K.m(); ++i)
    for (auto entry = K.begin(i); entry != K.end(i); ++entry)
      {
        largest   = std::max(largest, std::abs(entry->value()));
        asymmetry = std::max(asymmetry, std::abs(entry->value() - K.el(entry->column(), i)));
      }
  INFO("max |K_ij - K_ji| / max |K| = " << asymmetry / largest);
  TrilinosWrappers::MPI::Vector stable(r);
  SerialDirectSolver            direct(K);
  REQUIRE(direct.solve(K, stable, r));
  CHECK(direct.used_ldlt());
  CHECK_FALSE(direct.used_pivoting()); // positive definite: the pivots need no search
  CHECK(direct.negative_eigenvalues() == 0);
  CHECK(relative_difference(stable, klu_solution(K, r)) < 1e-5); // as above

  // -K: every eigenvalue negative, -K^-1 r.
  TrilinosWrappers::SparseMatrix negative;
  negative.copy_from(K);
  negative *= -1.0;
  TrilinosWrappers::MPI::Vector x(r);
  REQUIRE(direct.solve(negative, x, r));
  CHECK(direct.used_ldlt());
  CHECK(direct.negative_eigenvalues() == static_cast<int>(K.m()));
  x *= -1.0;
  CHECK(relative_difference(x, stable) < 1e-5);

  // K - 11 K_ii e_i e_i^T for a free DoF i: a rank-one decrease of a positive
  // definite K whose new K_ii < 0 has exactly one negative eigenvalue
  // (interlacing), the kind of tangent a Cholesky factorisation refuses.
  types::global_dof_index free_dof = 0;
  while (solver.space().fixed_dofs.is_constrained(free_dof))
    ++free_dof;
  TrilinosWrappers::SparseMatrix indefinite;
  indefinite.copy_from(K);
  indefinite.add(free_dof, free_dof, -11.0 * K.el(free_dof, free_dof));
  indefinite.compress(VectorOperation::add);
  REQUIRE(direct.solve(indefinite, x, r));
  CHECK(direct.used_ldlt());
  CHECK(direct.negative_eigenvalues() == 1);
  CHECK(relative_difference(x, klu_solution(indefinite, r)) < 1e-5);

  // An unsymmetric K (one off-diagonal entry K_ij changed by a tenth of K_ii,
  // K_ji not) goes to LU, which solves it as KLU does.
  types::global_dof_index row = 0, col = 0;
  for (types::global_dof_index i = 0; i < K.m() && row == col; ++i)
    for (auto entry = K.begin(i); entry != K.end(i); ++entry)
      if (entry->column() != i && entry->value() != 0.0)
        {
          row = i;
          col = entry->column();
          break;
        }
  REQUIRE(row != col);
  TrilinosWrappers::SparseMatrix unsymmetric;
  unsymmetric.copy_from(K);
  unsymmetric.add(row, col, 0.1 * std::abs(K.el(row, row)));
  unsymmetric.compress(VectorOperation::add);
  REQUIRE(unsymmetric.el(row, col) != unsymmetric.el(col, row));
  REQUIRE(direct.solve(unsymmetric, x, r));
  CHECK_FALSE(direct.used_ldlt());
  CHECK(relative_difference(x, klu_solution(unsymmetric, r)) < 1e-9);

  // The symmetry test's threshold, |K_ij - K_ji| <= 1e-12 max|K|, seen from
  // both sides with small changes of one entry: 1e-10 max|K| (a friction
  // tangent's asymmetry is far larger) goes to LU, 1e-14 max|K| (the
  // assembly's round-off, 1e-16 on P10) stays with LDL^T.
  double largest_entry = 0;
  for (types::global_dof_index i = 0; i < K.m(); ++i)
    for (auto entry = K.begin(i); entry != K.end(i); ++entry)
      largest_entry = std::max(largest_entry, std::abs(entry->value()));
  for (const auto &[change, symmetric] : {std::pair{1e-10, false}, std::pair{1e-14, true}})
    {
      TrilinosWrappers::SparseMatrix nearly;
      nearly.copy_from(K);
      nearly.add(row, col, change * largest_entry);
      nearly.compress(VectorOperation::add);
      REQUIRE(direct.solve(nearly, x, r));
      INFO("K_ij changed by " << change << " max|K|");
      CHECK(direct.used_ldlt() == symmetric);
      CHECK(relative_difference(x, klu_solution(nearly, r)) < (symmetric ? 1e-5 : 1e-9)); // as above
    }

  // Singular tangents are reported, not solved (the Newton iteration then
  // fails and the load step is cut): 0 K, symmetric, to LDL^T, and the
  // unsymmetric K with row `row` zeroed, to LU.
  TrilinosWrappers::SparseMatrix zero;
  zero.copy_from(K);
  zero *= 0.0;
  CHECK_FALSE(direct.solve(zero, x, r));
  CHECK(direct.used_ldlt());
  for (auto entry = unsymmetric.begin(row); entry != unsymmetric.end(row); ++entry)
    entry->value() = 0.0;
  CHECK_FALSE(direct.solve(unsymmetric, x, r));
  CHECK_FALSE(direct.used_ldlt());
}

// Two symmetric indefinite matrices that an LDL^T factorisation without
// pivoting cannot take, whatever its ordering. The adjacency matrix of a path
// of six nodes (eigenvalues 2 cos(k pi / 7), k = 1..6, three negative) has a
// zero diagonal: the first pivot is zero (MUMPS reports K singular). A dense
// random symmetric matrix with a diagonal of 1e-9 meets tiny pivots whose
// multipliers grow its entries (the solution's backward error is far above
// round-off). Either way the solver must notice and solve K by the pivoting
// factorisation (1x1 and 2x2 pivots), as accurately as its conditioning allows.
TEST_CASE("symmetric matrices whose pivots need a search are solved by the pivoting LDL^T",
          "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  const bool                             path_graph = GENERATE(true, false);
  const unsigned int                     n          = path_graph ? 6 : 40;
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  TrilinosWrappers::SparseMatrix K = symmetric_matrix(n, path_graph, [&](unsigned int i, unsigned int j) {
    return i == j ? (path_graph ? 0.0 : 1e-9) : path_graph ? 1.0 : value(random);
  });
  const TrilinosWrappers::MPI::Vector b = ramp(n);
  TrilinosWrappers::MPI::Vector       x(b), residual(b);

  SerialDirectSolver direct(K);
  REQUIRE(direct.solve(K, x, b));
  CHECK(direct.used_ldlt());
  CHECK(direct.used_pivoting());
  if (path_graph)
    CHECK(direct.negative_eigenvalues() == 3);
  K.vmult(residual, x);
  residual -= b;
  // A backward-stable solve: |b - K x| of the order of the round-off of K x.
  CHECK(residual.l2_norm() <= 1e-12 * (K.frobenius_norm() * x.l2_norm() + b.l2_norm()));
}

// Single-precision factors serve where GMRES with them as preconditioner
// converges, which is also where Wilkinson's stationary refinement stalls
// (cond(K) u_single >= 1, u_single = 6e-8):
//  - the 1D Laplacian tridiag(-1, 2, -1) of order 40 (cond 6.7e2): each
//    iteration gains at least -log10(cond u_single) = 4.4 digits, so from a
//    first residual near u_single two more reach 1e-12;
//  - the Hilbert matrix of order 8 (cond 1.5e10, cond u_single = 900, where
//    a stationary step loses digits): GMRES on K of order 8 ends in at most
//    8 iterations in exact arithmetic, whatever the preconditioner (7 taken);
//  - the Laplacian times 1e-50, whose entries single precision cannot hold
//    (its smallest number is 1.4e-45): its single factors are singular, and
//    the double factors solve, to the backward error of a stable solve.
TEST_CASE("single-precision factors are refined by GMRES where it converges, else double factors solve",
          "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  enum Case { laplacian, hilbert, underflow };
  const Case                           kind = GENERATE(laplacian, hilbert, underflow);
  const unsigned int                   n    = kind == hilbert ? 8 : 40;
  const TrilinosWrappers::SparseMatrix K    = symmetric_matrix(n, kind != hilbert, [&](unsigned int i, unsigned int j) {
    const double scale = kind == underflow ? 1e-50 : 1.0;
    return kind == hilbert ? 1.0 / (i + j + 1) : scale * (i == j ? 2.0 : -1.0);
  });
  const TrilinosWrappers::MPI::Vector b = ramp(K.m());
  TrilinosWrappers::MPI::Vector       x(b), r(b);

  SerialDirectSolver direct(K);
  REQUIRE(direct.solve(K, x, b));
  INFO("GMRES iterations " << direct.krylov_iterations_taken());
  if (kind == underflow)
    {
      CHECK(direct.last_factors() == SerialDirectSolver::Factors::unpivoted);
      CHECK(backward_error(K, x, b) <= 1e-12); // the double path's own bound
      return;
    }
  CHECK(direct.last_factors() == SerialDirectSolver::Factors::single);
  CHECK(direct.krylov_iterations_taken() <= (kind == laplacian ? 3u : 8u));
  // The solver's contract: a relative residual of 1e-12, or (what an
  // ill-conditioned K allows: the Hilbert matrix's solution is 1e9 times b)
  // the double factors' backward error bound. The test's product sums in
  // another order (1e-16).
  const auto meets_contract = [&](const TrilinosWrappers::MPI::Vector &x, const TrilinosWrappers::MPI::Vector &b) {
    K.vmult(r, x);
    r -= b;
    return kind == laplacian ? r.l2_norm() <= 1.01e-12 * b.l2_norm() : backward_error(K, x, b) <= 1.01e-12;
  };
  CHECK(meets_contract(x, b));
  // A second right-hand side reuses the single factors.
  TrilinosWrappers::MPI::Vector b2(b), x2(b);
  b2 *= -3.0;
  direct.solve_again(x2, b2);
  CHECK(meets_contract(x2, b2));
}

// A caller that needs less than the double factors' accuracy (Newton's
// inexact steps) gets it sooner: the refinement stops once the relative
// residual |b - K x| / |b| meets the caller's bound. On the 1D Laplacian of
// order 400 (cond 6.5e4) the backward error bound of 1e-12 corresponds to
// a far smaller relative residual than 1e-6, since |K| |x| >> |b|.
TEST_CASE("a refinement stops at the caller's relative residual", "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return;
  const TrilinosWrappers::SparseMatrix K =
    symmetric_matrix(400, true, [](unsigned int i, unsigned int j) { return i == j ? 2.0 : -1.0; });
  const TrilinosWrappers::MPI::Vector b = ramp(K.m());
  TrilinosWrappers::MPI::Vector       strict_x(b), loose_x(b), r(b);

  SerialDirectSolver strict(K), loose(K, 1e-6);
  REQUIRE(strict.solve(K, strict_x, b));
  REQUIRE(loose.solve(K, loose_x, b));
  REQUIRE(loose.last_factors() == SerialDirectSolver::Factors::single);
  INFO("GMRES iterations " << strict.krylov_iterations_taken() << " and " << loose.krylov_iterations_taken());
  CHECK(loose.krylov_iterations_taken() < strict.krylov_iterations_taken());
  K.vmult(r, loose_x);
  r -= b;
  CHECK(r.l2_norm() <= 1e-6 * b.l2_norm());
  CHECK(backward_error(K, strict_x, b) <= 1.01e-12);
}

TEST_CASE("every Direct solver package solves the tangent as KLU does", "[fem][solver]")
{
  // Each value of Solver/Direct solver package, through the one factory
  // the Newton solver uses, on the demo finger's tangent away from
  // equilibrium: the updates agree with KLU's within the forward-error
  // bound of the first test case (1e-5).
  for (const std::string package : {"MUMPS_or_UMFPACK", "Amesos_Mumps", "Amesos_Klu"})
    {
      INFO("Direct solver package = " << package);
      test::SolverFixture f(test::parameters_from_text(
        "package", test::bender_prm("Q2", 4,
                                    "subsection Solver\n  set Linear solver = direct\n"
                                    "  set Direct solver package = " +
                                      package + "\nend\n")));
      QuasiStaticSolver &solver = *f.solver;
      solver.set_displacement(test::smooth_displacement(solver, 2e-3, 0.05, 1));
      LoadState load;
      load.pressure = 2e4;
      REQUIRE(solver.assemble(load, true));
      std::ostringstream                   log;
      const std::unique_ptr<TangentSolver> tangent_solver =
        TangentSolver::create(f.prm.solver, solver.space(), log);
      TrilinosWrappers::MPI::Vector update(solver.negative_residual());
      REQUIRE(tangent_solver->solve(solver.tangent(), nullptr, solver.negative_residual(), update, false, 0.0));
      CHECK(relative_difference(update, klu_solution(solver)) < 1e-5);
    }
}

TEST_CASE("the iterative solver meets the Krylov tolerance, and a breakdown is a failed solve",
          "[fem][solver]")
{
  // Linear solver = iterative (GMRES with algebraic multigrid) on the demo
  // finger's tangent at rest: its contract is the relative residual
  // |b - K x| <= Krylov tolerance |b| from the Newton solver's start x = 0.
  // From a start far from the solution (x = b, a force read as a
  // displacement) AztecOO stops with an error code; the solve must
  // then fail with a named reason, which cuts the load step, not throw.
  test::SolverFixture f(test::parameters_from_text(
    "iterative", test::bender_prm("Q2", 4, "subsection Solver\n  set Linear solver = iterative\nend\n")));
  QuasiStaticSolver &solver = *f.solver;
  LoadState          load;
  load.pressure = 2e4;
  REQUIRE(solver.assemble(load, true));
  std::ostringstream                   log;
  const std::unique_ptr<TangentSolver> tangent_solver = TangentSolver::create(f.prm.solver, solver.space(), log);
  const TrilinosWrappers::MPI::Vector &b = solver.negative_residual();
  TrilinosWrappers::MPI::Vector        x(b), r(b);
  x = 0;
  REQUIRE(tangent_solver->solve(solver.tangent(), nullptr, b, x, false, 0.0));
  solver.tangent().vmult(r, x);
  r -= b;
  CHECK(r.l2_norm() <= f.prm.solver.krylov_tolerance * b.l2_norm());

  x = b;
  CHECK_FALSE(tangent_solver->solve(solver.tangent(), nullptr, b, x, false, 0.0));
  CHECK(log.str().find("GMRES broke down") != std::string::npos);
}
