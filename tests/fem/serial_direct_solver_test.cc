// SerialDirectSolver (UMFPACK on a copy of the Trilinos matrix) solves the
// same system as Trilinos' KLU: the demo finger's tangent with springs and
// pressure, at two deformed states, the second with the symbolic analysis of
// the first.
#include "fem_test_tools.h"

#include <softchain/fem/serial_direct_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <catch2/catch.hpp>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // K du = r by Trilinos' KLU, which shares no code with SerialDirectSolver.
  TrilinosWrappers::MPI::Vector klu_solution(const QuasiStaticSolver &solver)
  {
    TrilinosWrappers::MPI::Vector klu(solver.negative_residual());
    SolverControl                 control(1, 0);
    TrilinosWrappers::SolverDirect(control, TrilinosWrappers::SolverDirect::AdditionalData(
                                              false, "Amesos_Klu"))
      .solve(solver.tangent(), klu, solver.negative_residual());
    return klu;
  }

  double relative_difference(TrilinosWrappers::MPI::Vector a, const TrilinosWrappers::MPI::Vector &b)
  {
    a -= b;
    return a.l2_norm() / b.l2_norm();
  }
} // namespace

TEST_CASE("UMFPACK and KLU give the same Newton update", "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return; // SerialDirectSolver is the one-rank path
  test::SolverFixture f(test::parameters_from_text("serial_direct", test::bender_prm("Q2", 4)));
  QuasiStaticSolver &solver = *f.solver;
  solver.set_displacement(test::smooth_displacement(solver, 2e-3, 0.05, 1));
  LoadState load;
  load.pressure = 2e4;
  REQUIRE(solver.assemble(load, true));

  TrilinosWrappers::MPI::Vector umfpack(solver.negative_residual());
  SerialDirectSolver            direct(solver.tangent());
  direct.solve(solver.tangent(), umfpack, solver.negative_residual());
  // Both are backward stable: the difference is bounded by cond(K) * eps,
  // measured 8e-12 relative here; 1e-9 leaves room for other BLAS builds.
  CHECK(relative_difference(umfpack, klu_solution(solver)) < 1e-9);

  // A second state: new values in the same pattern. The solver keeps its
  // symbolic analysis and must still solve the new system, not the old one
  // (the two solutions differ by far more than the tolerance).
  const TrilinosWrappers::MPI::Vector first = umfpack;
  solver.set_displacement(test::smooth_displacement(solver, 6e-3, 0.05, 2));
  load.pressure = 4e4;
  REQUIRE(solver.assemble(load, true));
  direct.solve(solver.tangent(), umfpack, solver.negative_residual());
  CHECK(relative_difference(umfpack, klu_solution(solver)) < 1e-9);
  CHECK(relative_difference(first, umfpack) > 1e-3);
}
