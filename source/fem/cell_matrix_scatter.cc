#include <softchain/fem/cell_matrix_scatter.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace softchain::fem
{
  using namespace dealii;

  bool CellMatrixScatter::serves(const AffineConstraints<double> &constraints, MPI_Comm communicator)
  {
    if (Utilities::MPI::n_mpi_processes(communicator) != 1)
      return false;
    for (const auto &line : constraints.get_lines())
      if (!line.entries.empty() || line.inhomogeneity != 0.0)
        return false;
    return true;
  }

  CellMatrixScatter::CellMatrixScatter(const DoFHandler<3>                  &dof_handler,
                                       const AffineConstraints<double>      &constraints,
                                       const TrilinosWrappers::SparseMatrix &matrix)
    : constrained(dof_handler.n_dofs())
    , free_cell(dof_handler.get_triangulation().n_active_cells())
    , place(dof_handler.get_triangulation().n_active_cells())
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    AssertThrow(epetra.StorageOptimized() && epetra.NumMyRows() == static_cast<int>(dof_handler.n_dofs()),
                ExcMessage("CellMatrixScatter needs the whole matrix on one rank, in contiguous storage"));
    for (types::global_dof_index i = 0; i < constrained.size(); ++i)
      constrained[i] = constraints.is_constrained(i);
    // Each row's (global column, position) pairs, sorted by column.
    std::vector<std::vector<std::pair<types::global_dof_index, unsigned int>>> columns(epetra.NumMyRows());
    std::vector<unsigned int> row_start(epetra.NumMyRows()); // in the contiguous values
    double                   *first_value;
    int     n;
    epetra.ExtractMyRowView(0, n, first_value);
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        double *values;
        int    *local_columns;
        epetra.ExtractMyRowView(row, n, values);
        epetra.Graph().ExtractMyRowView(row, n, local_columns);
        const auto global_row  = epetra.GRID64(row);
        row_start[global_row]  = values - first_value;
        auto &row_columns      = columns[global_row];
        for (int k = 0; k < n; ++k)
          row_columns.emplace_back(epetra.GCID64(local_columns[k]), k);
        std::sort(row_columns.begin(), row_columns.end());
      }
    std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        auto &cell_place = place[cell->active_cell_index()];
        free_cell[cell->active_cell_index()] =
          std::none_of(dofs.begin(), dofs.end(), [&](const auto dof) { return constrained[dof]; });
        for (const auto row : dofs)
          for (const auto column : dofs)
            {
              // The pattern holds a constrained DoF's diagonal only.
              if ((constrained[row] || constrained[column]) && row != column)
                {
                  cell_place.push_back(0); // never written
                  continue;
                }
              const auto &row_columns = columns[row];
              const auto  at          = std::lower_bound(row_columns.begin(), row_columns.end(),
                                                         std::make_pair(column, 0u));
              AssertThrow(at != row_columns.end() && at->first == column,
                          ExcMessage("a cell coupling is missing from the tangent's pattern"));
              cell_place.push_back(row_start[row] + at->second);
            }
      }
  }

  // A constrained row's diagonal where its K_ii = 0: the mean |K_kk| of the
  // cell, or its mean row l1 norm if every K_kk = 0, or 1 (deal.II's rule, so
  // that the sums are the same).
  double CellMatrixScatter::substitute_diagonal(const FullMatrix<double> &cell_matrix)
  {
    const unsigned int n    = cell_matrix.m();
    double             mean = 0;
    for (unsigned int i = 0; i < n; ++i)
      mean += std::abs(cell_matrix(i, i));
    mean /= n;
    if (mean == 0.0)
      mean = cell_matrix.l1_norm() / n;
    return mean != 0.0 ? mean : 1.0;
  }

  void CellMatrixScatter::add(const unsigned int                          cell_index,
                              const std::vector<types::global_dof_index> &dofs,
                              const FullMatrix<double>                   *cell_matrix,
                              const Vector<double>                       &cell_rhs,
                              TrilinosWrappers::SparseMatrix             *matrix,
                              TrilinosWrappers::MPI::Vector              &rhs) const
  {
    const unsigned int n = dofs.size();
    if (!free_cell[cell_index])
      {
        std::vector<unsigned int> all(n);
        std::iota(all.begin(), all.end(), 0u);
        add(cell_index, dofs, all, cell_matrix, cell_rhs, matrix, rhs);
        return;
      }
    // No constrained DoF: the cell's entries in storage order.
    double *r = rhs.begin();
    for (unsigned int i = 0; i < n; ++i)
      r[dofs[i]] += cell_rhs(i);
    if (!cell_matrix)
      return;
    double *values;
    int     n_row;
    matrix->trilinos_matrix().ExtractMyRowView(0, n_row, values);
    const unsigned int *to    = place[cell_index].data();
    const double       *entry = &(*cell_matrix)(0, 0);
    for (unsigned int k = 0; k < n * n; ++k)
      values[to[k]] += entry[k];
  }

  void CellMatrixScatter::add(const unsigned int                          cell_index,
                              const std::vector<types::global_dof_index> &dofs,
                              const std::vector<unsigned int>            &local,
                              const FullMatrix<double>                   *block,
                              const Vector<double>                       &block_rhs,
                              TrilinosWrappers::SparseMatrix             *matrix,
                              TrilinosWrappers::MPI::Vector              &rhs) const
  {
    const unsigned int n = dofs.size(), m = local.size();
    double            *r = rhs.begin();
    for (unsigned int i = 0; i < m; ++i)
      if (!constrained[dofs[local[i]]])
        r[dofs[local[i]]] += block_rhs(i);
    if (!block)
      return;
    double *values;
    int     n_row;
    matrix->trilinos_matrix().ExtractMyRowView(0, n_row, values);
    const unsigned int *to = place[cell_index].data();
    for (unsigned int i = 0; i < m; ++i)
      {
        const double      *row     = &(*block)(i, 0);
        const unsigned int cell_row = local[i] * n;
        if (constrained[dofs[local[i]]])
          {
            const double diagonal = std::abs(row[i]);
            values[to[cell_row + local[i]]] += diagonal != 0.0 ? diagonal : substitute_diagonal(*block);
            continue;
          }
        for (unsigned int j = 0; j < m; ++j)
          if (!constrained[dofs[local[j]]])
            values[to[cell_row + local[j]]] += row[j];
      }
  }
} // namespace softchain::fem
