#include <softchain/serial_direct_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>

namespace softchain
{
  SerialDirectSolver::SerialDirectSolver(const TrilinosWrappers::SparseMatrix &matrix)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()) == 1,
                ExcMessage("SerialDirectSolver runs on one MPI rank only"));
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    DynamicSparsityPattern  dsp(matrix.m(), matrix.n());
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        int  n;
        int *columns;
        epetra.Graph().ExtractMyRowView(row, n, columns);
        for (int k = 0; k < n; ++k)
          dsp.add(row, epetra.GCID(columns[k]));
      }
    pattern.copy_from(dsp);
    copy.reinit(pattern);
  }

  void SerialDirectSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                                 TrilinosWrappers::MPI::Vector        &solution,
                                 const TrilinosWrappers::MPI::Vector  &rhs)
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        int     n;
        double *values;
        int    *columns;
        epetra.ExtractMyRowView(row, n, values, columns);
        for (int k = 0; k < n; ++k)
          copy.set(row, epetra.GCID(columns[k]), values[k]);
      }
    umfpack.initialize(copy);

    Vector<double> x(rhs);
    umfpack.solve(x);
    for (types::global_dof_index i = 0; i < x.size(); ++i)
      solution[i] = x[i];
    solution.compress(VectorOperation::insert);
  }
} // namespace softchain
