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

  // The places in two passes without searches: every cell's DoFs and, per
  // DoF, the cell rows it heads; then, row by row, each column's position
  // in the row's storage is written to a table indexed by column (stamped
  // with the row, so that an entry missing from the pattern is found), and
  // every cell row of that DoF reads its entries' places from it.
  CellMatrixScatter::CellMatrixScatter(const DoFHandler<3>                  &dof_handler,
                                       const AffineConstraints<double>      &constraints,
                                       const TrilinosWrappers::SparseMatrix &matrix)
    : constrained(dof_handler.n_dofs())
    , free_cell(dof_handler.get_triangulation().n_active_cells())
    , dofs_per_cell(dof_handler.get_fe().n_dofs_per_cell())
    , all_local(dofs_per_cell)
  {
    std::iota(all_local.begin(), all_local.end(), 0u);
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const auto              n_dofs = dof_handler.n_dofs();
    AssertThrow(epetra.StorageOptimized() && epetra.NumMyRows() == static_cast<int>(n_dofs),
                ExcMessage("CellMatrixScatter needs the whole matrix on one rank, in contiguous storage"));
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      constrained[i] = constraints.is_constrained(i);

    const unsigned int n = dofs_per_cell, n_cells = free_cell.size();
    std::vector<types::global_dof_index> cell_dofs(std::size_t(n_cells) * n), dofs(n);
    std::vector<unsigned int>            rows_start(n_dofs + 1, 0); // cell rows per DoF
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + std::size_t(cell->active_cell_index()) * n);
        free_cell[cell->active_cell_index()] =
          std::none_of(dofs.begin(), dofs.end(), [&](const auto dof) { return constrained[dof]; });
        for (const auto dof : dofs)
          ++rows_start[dof + 1];
      }
    std::partial_sum(rows_start.begin(), rows_start.end(), rows_start.begin());
    std::vector<unsigned int> cell_rows(rows_start.back()), next(rows_start.begin(), rows_start.end() - 1);
    for (std::size_t k = 0; k < cell_dofs.size(); ++k)
      cell_rows[next[cell_dofs[k]]++] = k; // cell k / n, local row k % n

    std::vector<types::global_dof_index> global_column(epetra.ColMap().NumMyElements());
    for (std::size_t c = 0; c < global_column.size(); ++c)
      global_column[c] = epetra.GCID64(c);
    std::vector<unsigned int>            position(n_dofs);
    std::vector<types::global_dof_index> stamp(n_dofs, numbers::invalid_dof_index);
    place.assign(std::size_t(n_cells) * n * n, 0); // a dropped entry keeps 0: never written
    double *first_value;
    int     length;
    epetra.ExtractMyRowView(0, length, first_value);
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        double *values;
        int    *local_columns;
        epetra.ExtractMyRowView(row, length, values);
        epetra.Graph().ExtractMyRowView(row, length, local_columns);
        const types::global_dof_index global_row = epetra.GRID64(row);
        for (int k = 0; k < length; ++k)
          {
            position[global_column[local_columns[k]]] = (values - first_value) + k;
            stamp[global_column[local_columns[k]]]    = global_row;
          }
        for (unsigned int r = rows_start[global_row]; r < rows_start[global_row + 1]; ++r)
          {
            const std::size_t cell = cell_rows[r] / n, i = cell_rows[r] % n;
            for (unsigned int j = 0; j < n; ++j)
              {
                const auto column = cell_dofs[cell * n + j];
                // The pattern holds a constrained DoF's diagonal only.
                if ((constrained[global_row] || constrained[column]) && global_row != column)
                  continue;
                AssertThrow(stamp[column] == global_row,
                            ExcMessage("a cell coupling is missing from the tangent's pattern"));
                place[(cell * n + i) * n + j] = position[column];
              }
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

  double *CellMatrixScatter::values_of(TrilinosWrappers::SparseMatrix &matrix)
  {
    double *values;
    int     n_row;
    matrix.trilinos_matrix().ExtractMyRowView(0, n_row, values);
    return values;
  }

  const unsigned int *CellMatrixScatter::places_of(const unsigned int cell_index) const
  {
    return &place[std::size_t(cell_index) * dofs_per_cell * dofs_per_cell];
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
        add(cell_index, dofs, all_local, cell_matrix, cell_rhs, matrix, rhs);
        return;
      }
    // No constrained DoF: the cell's entries in storage order.
    double *r = rhs.begin();
    for (unsigned int i = 0; i < n; ++i)
      r[dofs[i]] += cell_rhs(i);
    if (!cell_matrix)
      return;
    double             *values = values_of(*matrix);
    const unsigned int *to     = places_of(cell_index);
    const double       *entry  = &(*cell_matrix)(0, 0);
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
    double             *values = values_of(*matrix);
    const unsigned int *to     = places_of(cell_index);
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
