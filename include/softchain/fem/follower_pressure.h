#pragma once
// FollowerPressure: the cavity pressure p acting on the deformed cavity
// surface. In the reference configuration (Nanson's formula) the traction is
//     t0 = -p cof(F) N,   cof(F) = J F^-T,
// with N the body's outward normal (pointing into the cavity), so the wall is
// pushed away from the cavity. Its linearisation is the non-symmetric load
// stiffness
//     d cof(F)[G] = J ((F^-T : G) F^-T - F^-T G^T F^-T),   G = Grad du,
// (Wriggers, Nonlinear Finite Element Methods, Sec. 4.2.5). This is the
// continuum form of the paper's per-face force p A_f n_f / 3 (Skouras et al.).
// For the shape function e_d phi_b (node b), G = e_d (x) Grad phi_b, so with
// n = F^-T N and g_b = F^-T Grad phi_b the load stiffness of the node pair
// (a, b) is the 3x3 block
//     K[c,a ; d,b] = p int phi_a J (n_c g_b,d - g_b,c n_d) dA0,
// assembled node by node, only for the nodes a of the cavity face
// (phi_a = 0 on it for the others).
#include <softchain/fem/cell_matrix_scatter.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace softchain::fem
{
  class FollowerPressure
  {
  public:
    explicit FollowerPressure(const FiniteElementSpace &space);

    // rhs += f_ext, matrix -= d f_ext / du (if given), for pressure p. With
    // `places` (built for `constraints`), each cavity cell's sums go to
    // their stored places in the matrix instead of through deal.II's
    // column searches (CellMatrixScatter).
    void assemble(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u,
                  double                               pressure,
                  const dealii::AffineConstraints<double>     &constraints,
                  dealii::TrilinosWrappers::SparseMatrix      *matrix,
                  dealii::TrilinosWrappers::MPI::Vector       &rhs,
                  const CellMatrixScatter                     *places = nullptr) const;

    // Total pressure force on the walls (zero for a closed cavity).
    dealii::Tensor<1, 3> resultant(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u, double pressure) const;
    // Enclosed cavity volume, V = -1/3 int x . cof(F) N dA (divergence theorem).
    double cavity_volume(const dealii::TrilinosWrappers::MPI::Vector &ghosted_u) const;
    bool   has_cavity() const { return n_faces > 0; }

  private:
    const FiniteElementSpace &space;
    unsigned long             n_faces; // cavity faces on all ranks
    // node_dofs[a][c]: the cell DoF of e_c phi_a (node_dof_table).
    std::vector<std::array<unsigned int, 3>> node_dofs;

    // Calls f(fe_face_values, q, F, cof(F) N) at each cavity quadrature point
    // of the locally owned cells.
    template <typename Function>
    void for_each_cavity_point(const dealii::TrilinosWrappers::MPI::Vector &u, Function f) const;
  };
} // namespace softchain::fem
