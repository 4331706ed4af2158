#pragma once
// CellMatrixScatter: adds cell matrices and vectors into the tangent and the
// residual on one MPI rank, through the place of each cell entry in the
// Trilinos matrix's row storage, found once per sparsity pattern.
//
// deal.II's AffineConstraints::distribute_local_to_global into a Trilinos
// matrix looks up every entry's column in its row (Epetra's binary search and
// index maps) on every assembly: on P10's P2 tetrahedra that was as much CPU
// time as the cell kernel, and it runs in the serial copier of the
// WorkStream, where it limits the second thread (docs/history.md). For the
// constraints of a Newton update without a tip motion -- homogeneous
// Dirichlet lines u_i = 0 only (clamped base, symmetry faces) -- the same
// sums are formed here from stored places: a constrained row and column are
// dropped, the rhs entry of a constrained row stays 0, and its diagonal gets
// |K_ii| of the cell matrix (the mean |K_kk| of the cell if that is 0), as
// deal.II does, so the assembled system is the same to the last bit.
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace softchain::fem
{
  class CellMatrixScatter
  {
  public:
    // Whether `constraints` are homogeneous Dirichlet lines only and the
    // problem lives on one rank: the cases this class serves.
    static bool serves(const dealii::AffineConstraints<double> &constraints, MPI_Comm communicator);

    // The places of every cell's entries in `matrix` (its pattern final);
    // `constraints` must be served (see serves()).
    CellMatrixScatter(const dealii::DoFHandler<3>             &dof_handler,
                      const dealii::AffineConstraints<double> &constraints,
                      const dealii::TrilinosWrappers::SparseMatrix &matrix);

    // matrix += the cell matrix (if given), rhs += the cell vector, for the
    // active cell `cell_index` with DoFs `dofs` (in the cell's order).
    void add(unsigned int                                      cell_index,
             const std::vector<dealii::types::global_dof_index> &dofs,
             const dealii::FullMatrix<double>                  *cell_matrix,
             const dealii::Vector<double>                      &cell_rhs,
             dealii::TrilinosWrappers::SparseMatrix            *matrix,
             dealii::TrilinosWrappers::MPI::Vector             &rhs) const;
    // The same for a block of the cell matrix: its rows and columns are the
    // cell's DoFs local[0], local[1], ... (e.g. a face's).
    void add(unsigned int                                      cell_index,
             const std::vector<dealii::types::global_dof_index> &dofs,
             const std::vector<unsigned int>                   &local,
             const dealii::FullMatrix<double>                  *block,
             const dealii::Vector<double>                      &block_rhs,
             dealii::TrilinosWrappers::SparseMatrix            *matrix,
             dealii::TrilinosWrappers::MPI::Vector             &rhs) const;

  private:
    static double substitute_diagonal(const dealii::FullMatrix<double> &cell_matrix);
    // The matrix's values in their contiguous storage; a cell's places in them.
    static double      *values_of(dealii::TrilinosWrappers::SparseMatrix &matrix);
    const unsigned int *places_of(unsigned int cell_index) const;

    std::vector<bool> constrained; // per DoF
    std::vector<bool> free_cell;   // per active cell: none of its DoFs constrained
    unsigned int      dofs_per_cell;
    std::vector<unsigned int> all_local; // 0, 1, ..., dofs_per_cell - 1: a whole cell as a block
    // Per active cell, for its (i, j) in row-major order: the index of the
    // entry in the matrix's contiguous values (dofs_per_cell^2 per cell).
    std::vector<unsigned int> place;
  };
} // namespace softchain::fem
