// SerialDirectSolver (UMFPACK on a copy of the Trilinos matrix) solves the
// same system as Trilinos' KLU: the demo finger's tangent with springs and
// pressure, at a deformed state.
#include "fem_test_tools.h"

#include <softchain/serial_direct_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <catch2/catch.hpp>

using namespace softchain;

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

  TrilinosWrappers::MPI::Vector umfpack(solver.negative_residual()), klu(umfpack);
  SerialDirectSolver(solver.tangent()).solve(solver.tangent(), umfpack, solver.negative_residual());
  SolverControl control(1, 0);
  TrilinosWrappers::SolverDirect(control, TrilinosWrappers::SolverDirect::AdditionalData(
                                            false, "Amesos_Klu"))
    .solve(solver.tangent(), klu, solver.negative_residual());

  // Both are backward stable: the difference is bounded by cond(K) * eps,
  // measured 8e-12 relative here; 1e-9 leaves room for other BLAS builds.
  klu -= umfpack;
  CHECK(klu.l2_norm() / umfpack.l2_norm() < 1e-9);
}
