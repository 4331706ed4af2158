#pragma once
// FollowerPressure: the cavity pressure p acting on the deformed cavity
// surface. In the reference configuration (Nanson's formula) the traction is
//     t0 = -p cof(F) N,   cof(F) = J F^-T,
// with N the body's outward normal (pointing into the cavity), so the wall is
// pushed away from the cavity. This is the continuum form of the paper's
// per-face force p A_f n_f / 3 (Skouras et al.).
//
// cof(F) N depends on the surface's own deformation only: with orthonormal
// reference tangents T1, T2 of the face (T1 x T2 = N),
//     cof(F) N = F T1 x F T2,   F Tk = Tk + sum_b u_b (Grad phi_b . Tk),
// and only the face's nodes b have phi_b or its tangential derivatives
// nonzero on it. The load on node a of the face is
//     f_a = -p int phi_a (F T1 x F T2) dA0,
// and its derivative along the displacement w of node b is
//     df_a/du_b w = -p int phi_a  w x v_b  dA0,
//     v_b = (Grad phi_b . T1) F T2 - (Grad phi_b . T2) F T1
// (the linearised area vector, Wriggers, Nonlinear Finite Element Methods,
// Sec. 4.2.5, in surface form), a non-symmetric load stiffness that couples
// the face's nodes only. The reference data (T1, T2, dA0 and, per face node,
// phi and its two tangential derivatives at each quadrature point) are fixed
// in the reference configuration and computed once, so an assembly evaluates
// no mapping and no cell shape functions.
#include <softchain/fem/cell_matrix_scatter.h>
#include <softchain/fem/finite_element_space.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace softchain::fem
{
  class FollowerPressure
  {
  public:
    explicit FollowerPressure(const FiniteElementSpace &space);

    // rhs += f_ext, matrix -= d f_ext / du (if given), for pressure p. With
    // `places` (built for `constraints`), each face's sums go to their
    // stored places in the matrix instead of through deal.II's column
    // searches (CellMatrixScatter).
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
    // A quadrature point of a cavity face in the reference configuration.
    struct ReferencePoint
    {
      dealii::Tensor<1, 3> T1, T2; // orthonormal tangents, T1 x T2 = N
      dealii::Point<3>     X;      // position
      double               dA;     // area weight (JxW)
    };
    // A face node's shape function at a point: phi, Grad phi . T1, Grad phi . T2.
    struct NodeTerms
    {
      double phi, d1, d2;
    };
    // A cavity face of a locally owned cell: its nodes (indices into
    // node_dofs), its points from `first_point` on and their node terms
    // from `first_term` on (point-major, nodes.size() per point).
    struct CavityFace
    {
      dealii::DoFHandler<3>::active_cell_iterator cell;
      std::vector<unsigned int>                   nodes;
      std::size_t                                 first_point;
      std::size_t                                 first_term;
    };
    // The deformed tangents F T1, F T2 at a point; their cross product is
    // the area vector cof(F) N per unit reference area.
    struct DeformedTangents
    {
      dealii::Tensor<1, 3> FT1, FT2;
      dealii::Tensor<1, 3> area() const { return cross_product_3d(FT1, FT2); }
    };
    // A face's point q in both configurations.
    struct SurfacePoint
    {
      const ReferencePoint &reference;
      const NodeTerms      *nodes; // the face's nodes, in CavityFace::nodes' order
      DeformedTangents      deformed;
    };

    const FiniteElementSpace &space;
    unsigned long             n_faces;         // cavity faces on all ranks
    unsigned int              points_per_face; // the face quadrature's
    // node_dofs[a][c]: the cell DoF of e_c phi_a (node_dof_table).
    std::vector<std::array<unsigned int, 3>> node_dofs;
    std::vector<CavityFace>                  faces;
    std::vector<ReferencePoint>              points;
    std::vector<NodeTerms>                   terms;

    void add_face(const dealii::FEFaceValues<3> &fe_face,
                  const dealii::DoFHandler<3>::active_cell_iterator &cell);
    // Calls f(face, dofs, u_nodes) for each cavity face of the locally owned
    // cells, with its cell's DoFs and the displacements of its nodes.
    template <typename Function>
    void for_each_face(const dealii::TrilinosWrappers::MPI::Vector &u, Function f) const;
    SurfacePoint at(const CavityFace &face, unsigned int q,
                    const std::vector<dealii::Tensor<1, 3>> &u_nodes) const;
  };
} // namespace softchain::fem
