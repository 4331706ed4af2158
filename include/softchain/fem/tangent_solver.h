#pragma once
// TangentSolver: x = K^-1 b for Newton's corrections, K the tangent. One
// factory, create(), chooses the solver from subsection Solver once:
//  - direct on one rank with Direct solver package = MUMPS_or_UMFPACK:
//    SoftChain's own SerialDirectSolver (MUMPS's LDL^T where K is symmetric;
//    GMRES on K with the LDL^T factors of K - N where that is symmetric, N
//    the friction's unsymmetric part; else UMFPACK's LU), which keeps its
//    symbolic analysis across Newton iterations and its factors for a
//    simplified Newton correction;
//  - direct otherwise: Trilinos' Amesos (Amesos_Mumps for MUMPS_or_UMFPACK
//    on several ranks, else the package named);
//  - iterative (Linear solver = iterative, or auto above Direct solver
//    maximum DoFs): GMRES preconditioned by algebraic multigrid (ML) with
//    the rigid-body translations as near-null space.
// A solve that fails (a singular K, a GMRES that does not converge) returns
// false, which fails the Newton iteration and cuts the load step.
#include <softchain/fem/finite_element_space.h>
#include <softchain/fem/parameters.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <ostream>

namespace softchain::fem
{
  class TangentSolver
  {
  public:
    virtual ~TangentSolver() = default;

    // x = K^-1 b; `same_tangent`: with the factors of the last solve where
    // the solver keeps them (keeps_factorisation()), else with K.
    // `forcing`: the relative residual |b - K x| <= forcing |b| a solve that
    // refines or iterates may stop at (0: its own tolerance).
    // `unsymmetric_part`: nullptr, or a part N of K such that K - N is
    // symmetric where the rest of K is (the friction's, ObstacleContact),
    // for a solver that can use it.
    virtual bool solve(const dealii::TrilinosWrappers::SparseMatrix &K,
                       const dealii::TrilinosWrappers::SparseMatrix *unsymmetric_part,
                       const dealii::TrilinosWrappers::MPI::Vector  &b,
                       dealii::TrilinosWrappers::MPI::Vector        &x,
                       bool                                          same_tangent,
                       double                                        forcing) = 0;
    virtual bool keeps_factorisation() const { return false; }
    // K's sparsity pattern changed: a kept analysis of the old one is void.
    virtual void pattern_changed() {}

    // The solver subsection Solver asks for, on `space`'s DoFs and ranks.
    static std::unique_ptr<TangentSolver> create(const SolverParameters   &prm,
                                                 const FiniteElementSpace &space, std::ostream &log);
  };
} // namespace softchain::fem
