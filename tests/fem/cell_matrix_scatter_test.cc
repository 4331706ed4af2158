// CellMatrixScatter adds cell matrices and vectors through stored places:
// the same global matrix and vector, entry by entry and to the last bit, as
// deal.II's AffineConstraints::distribute_local_to_global, on the demo
// finger's Q2 and P2 meshes with their clamped base (constrained rows and
// columns, and their diagonal rule, included), for seeded random cell data,
// and for the follower pressure's cavity faces (blocks of their cells' DoFs)
// at a deformed state.
#include "fem_test_tools.h"

#include <softchain/fem/cell_matrix_scatter.h>

#include <catch2/catch.hpp>

#include <random>

using namespace dealii;
using namespace softchain;
using namespace softchain::fem;

namespace
{
  // The solver's matrix and residual vector, zeroed, twice: once summed by
  // deal.II's distribution, once through the stored places.
  struct TwoSums
  {
    TrilinosWrappers::SparseMatrix by_deal_ii, by_places;
    TrilinosWrappers::MPI::Vector  rhs_deal_ii, rhs_places;

    explicit TwoSums(const QuasiStaticSolver &solver)
      : rhs_deal_ii(solver.negative_residual())
      , rhs_places(solver.negative_residual())
    {
      by_deal_ii.reinit(solver.tangent());
      by_places.reinit(solver.tangent());
      by_deal_ii  = 0;
      by_places   = 0;
      rhs_deal_ii = 0;
      rhs_places  = 0;
    }

    void compress()
    {
      for (auto *m : {&by_deal_ii, &by_places})
        m->compress(VectorOperation::add);
      for (auto *v : {&rhs_deal_ii, &rhs_places})
        v->compress(VectorOperation::add);
    }

    // Matrix and vector entries that differ in any bit.
    unsigned int differing() const
    {
      unsigned int count = 0;
      for (types::global_dof_index i = 0; i < by_deal_ii.m(); ++i)
        for (auto entry = by_deal_ii.begin(i); entry != by_deal_ii.end(i); ++entry)
          count += entry->value() != by_places.el(i, entry->column());
      for (types::global_dof_index i = 0; i < rhs_deal_ii.size(); ++i)
        count += rhs_deal_ii[i] != rhs_places[i];
      return count;
    }

    unsigned int nonzero_entries() const
    {
      unsigned int count = 0;
      for (types::global_dof_index i = 0; i < by_deal_ii.m(); ++i)
        for (auto entry = by_deal_ii.begin(i); entry != by_deal_ii.end(i); ++entry)
          count += entry->value() != 0.0;
      return count;
    }
  };
} // namespace

TEST_CASE("cell entries added by their stored places equal deal.II's distribution", "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return; // the one-rank path
  const std::string element = GENERATE(as<std::string>{}, "Q2", "P2");
  INFO(element);
  test::SolverFixture       f(test::parameters_from_text("scatter", test::bender_prm(element, 4)));
  const auto               &space = f.solver->space();
  REQUIRE(CellMatrixScatter::serves(space.fixed_dofs, space.communicator));
  REQUIRE(space.fixed_dofs.n_constraints() > 0);
  TwoSums sums(*f.solver);
  const CellMatrixScatter scatter(space.dof_handler, space.fixed_dofs, sums.by_places);

  const unsigned int                   n = space.fe->n_dofs_per_cell();
  FullMatrix<double>                   cell_matrix(n, n);
  Vector<double>                       cell_rhs(n);
  std::vector<types::global_dof_index> dofs(n);
  std::mt19937                         random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const auto &cell : space.dof_handler.active_cell_iterators())
    {
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < n; ++i)
        {
          cell_rhs(i) = value(random);
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix(i, j) = value(random);
        }
      cell_matrix(0, 0) = 0.0; // exercises the mean-diagonal rule where DoF 0 is clamped
      space.fixed_dofs.distribute_local_to_global(cell_matrix, cell_rhs, dofs, sums.by_deal_ii,
                                                  sums.rhs_deal_ii);
      scatter.add(cell->active_cell_index(), dofs, &cell_matrix, cell_rhs, &sums.by_places,
                  sums.rhs_places);
    }
  sums.compress();
  CHECK(sums.nonzero_entries() > 0);
  CHECK(sums.differing() == 0);
}

TEST_CASE("the follower pressure added by places equals deal.II's distribution", "[fem][solver]")
{
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    return; // the one-rank path
  const std::string element = GENERATE(as<std::string>{}, "Q2", "P2");
  INFO(element);
  test::SolverFixture f(test::parameters_from_text("scatter_pressure", test::bender_prm(element, 4)));
  f.solver->set_displacement(test::smooth_displacement(*f.solver, 2e-3, 0.05, 3));
  const auto &space = f.solver->space();
  TwoSums                 sums(*f.solver);
  const CellMatrixScatter scatter(space.dof_handler, space.fixed_dofs, sums.by_places);
  const auto             &pressure = f.solver->pressure_load();
  pressure.assemble(f.solver->displacement(), 3e3, space.fixed_dofs, &sums.by_deal_ii,
                    sums.rhs_deal_ii);
  pressure.assemble(f.solver->displacement(), 3e3, space.fixed_dofs, &sums.by_places,
                    sums.rhs_places, &scatter);
  sums.compress();
  CHECK(sums.nonzero_entries() > 0);
  CHECK(sums.rhs_deal_ii.l2_norm() > 0);
  CHECK(sums.differing() == 0);
}
