#include <softchain/fem/serial_direct_solver.h>
#include <softchain/fem/tangent_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

namespace softchain::fem
{
  using namespace dealii;

  namespace
  {
    // SerialDirectSolver, made at the first solve (it analyses K's pattern).
    class KeptFactorsSolver : public TangentSolver
    {
    public:
      KeptFactorsSolver(const SolverParameters &prm, std::ostream &log)
        : prm(prm)
        , log(log)
      {}
      bool solve(const TrilinosWrappers::SparseMatrix &K, const TrilinosWrappers::SparseMatrix *unsymmetric_part,
                 const TrilinosWrappers::MPI::Vector &b, TrilinosWrappers::MPI::Vector &x,
                 const bool same_tangent, const double forcing) override
      {
        // The linear residual Newton's step may leave (NewtonSolver), else a
        // hundredth of the residual tolerance relative to |b|.
        if (!factors)
          factors = std::make_unique<SerialDirectSolver>(K);
        factors->accept_relative_residual(forcing > 0 ? forcing : prm.residual_tolerance / 100);
        if (same_tangent)
          {
            factors->solve_again(x, b);
            return true;
          }
        if (factors->solve(K, x, b, unsymmetric_part))
          return true;
        log << "      the tangent is singular\n";
        return false;
      }
      bool keeps_factorisation() const override { return true; }
      void pattern_changed() override { factors.reset(); }

    private:
      const SolverParameters             &prm;
      std::ostream                       &log;
      std::unique_ptr<SerialDirectSolver> factors;
    };

    // Trilinos' Amesos, a new factorisation per solve.
    class AmesosSolver : public TangentSolver
    {
    public:
      AmesosSolver(const SolverParameters &prm)
        : prm(prm)
        , package(prm.direct_solver_package == SolverParameters::DirectPackage::amesos_klu ?
                    "Amesos_Klu" :
                    "Amesos_Mumps")
      {}
      bool solve(const TrilinosWrappers::SparseMatrix &K, const TrilinosWrappers::SparseMatrix *,
                 const TrilinosWrappers::MPI::Vector &b, TrilinosWrappers::MPI::Vector &x, bool, double) override
      {
        SolverControl                  control(1000, prm.krylov_tolerance * b.l2_norm());
        TrilinosWrappers::SolverDirect solver(control, TrilinosWrappers::SolverDirect::AdditionalData(false, package));
        solver.solve(K, x, b);
        return true;
      }

    private:
      const SolverParameters &prm;
      const std::string       package;
    };

    // GMRES(200) with ML's smoothed aggregation, the translations as
    // constant modes, to the Krylov tolerance.
    class AmgGmresSolver : public TangentSolver
    {
    public:
      AmgGmresSolver(const SolverParameters &prm, const FiniteElementSpace &space, std::ostream &log)
        : prm(prm)
        , log(log)
      {
        DoFTools::extract_constant_modes(space.dof_handler, ComponentMask(3, true), amg.constant_modes);
        amg.elliptic              = true;
        amg.higher_order_elements = space.degree > 1;
        amg.smoother_sweeps       = 2;
        amg.aggregation_threshold = 0.02;
      }
      bool solve(const TrilinosWrappers::SparseMatrix &K, const TrilinosWrappers::SparseMatrix *,
                 const TrilinosWrappers::MPI::Vector &b, TrilinosWrappers::MPI::Vector &x, bool, double) override
      {
        SolverControl                     control(1000, prm.krylov_tolerance * b.l2_norm());
        TrilinosWrappers::PreconditionAMG preconditioner;
        preconditioner.initialize(K, amg);
        TrilinosWrappers::SolverGMRES solver(control, TrilinosWrappers::SolverGMRES::AdditionalData(false, 200));
        try
          {
            solver.solve(K, x, b, preconditioner);
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            log << "      GMRES did not converge in " << failure.last_step << " iterations (residual "
                << failure.last_residual << ")\n";
            return false;
          }
        catch (const ExceptionBase &)
          {
            // AztecOO stops with an error code where GMRES breaks down or
            // loses precision: a failed solve, which cuts the load step,
            // rather than an exception that ends the run.
            log << "      GMRES broke down (AztecOO stopped with an error)\n";
            return false;
          }
        return true;
      }

    private:
      const SolverParameters                           &prm;
      std::ostream                                     &log;
      TrilinosWrappers::PreconditionAMG::AdditionalData amg;
    };
  } // namespace

  std::unique_ptr<TangentSolver> TangentSolver::create(const SolverParameters &prm, const FiniteElementSpace &space,
                                                       std::ostream &log)
  {
    using LinearSolver = SolverParameters::LinearSolver;
    const bool direct  = prm.linear_solver == LinearSolver::direct ||
                        (prm.linear_solver == LinearSolver::automatic &&
                         space.dof_handler.n_dofs() <= prm.direct_solver_max_dofs);
    if (!direct)
      return std::make_unique<AmgGmresSolver>(prm, space, log);
    if (prm.direct_solver_package == SolverParameters::DirectPackage::mumps_or_umfpack &&
        Utilities::MPI::n_mpi_processes(space.communicator) == 1)
      return std::make_unique<KeptFactorsSolver>(prm, log);
    return std::make_unique<AmesosSolver>(prm);
  }
} // namespace softchain::fem
