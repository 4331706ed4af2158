#pragma once
// HyperelasticCell: the solid's internal force and tangent on one cell
// (total Lagrangian, integrated over the reference cell with the spatial
// stress and tangent pushed forward, as in deal.II step-44), written for the
// vector-valued Lagrange elements SoftChain uses: shape function i is
// e_c phi_a, one scalar function phi_a (node a) times one unit vector e_c.
// With g_a = grad_x phi_a = F^-T grad_X phi_a the spatial gradient, tau the
// Kirchhoff stress and c the spatial tangent (Jc in step-44),
//     f_int[c,a]      = int  (tau g_a)_c  dV0,
//     K[c,a ; d,b]    = int  g_a^k c_ckdl g_b^l  +  delta_cd g_a . tau g_b  dV0
// (material and geometric parts; c has minor symmetries, so sym(e_c (x) g_a)
// may be replaced by e_c (x) g_a). Working per node pair (a, b) instead of
// per DoF pair, with A_a[c][d][l] = g_a^k c_ckdl formed once per node, costs
// 27 multiply-adds per 3x3 block and uses K's symmetry (b <= a), where the
// DoF-by-DoF contraction of symmetric tensors costs several times as much.
#include <softchain/fem/hyperelastic_material.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace softchain::fem
{
  class HyperelasticCell
  {
  public:
    // `fe`: three copies of one scalar element (FESystem(base, 3)).
    explicit HyperelasticCell(const dealii::FiniteElement<3> &fe);

    // Adds -f_int + int N body_force dV0 to `rhs` and, if `matrix` is given,
    // K to it, at the quadrature points of `fe_values` (reinit on the cell)
    // with displacement gradients `grad_u`. Returns false, leaving the
    // outputs partly filled, if det F <= 0 at a quadrature point.
    bool assemble(const dealii::FEValues<3>                &fe_values,
                  const std::vector<dealii::Tensor<2, 3>>  &grad_u,
                  const HyperelasticMaterial               &material,
                  const dealii::Tensor<1, 3>               &body_force,
                  dealii::FullMatrix<double>               *matrix,
                  dealii::Vector<double>                   &rhs);

  private:
    void add_tangent(const dealii::SymmetricTensor<4, 3> &c, double JxW);
    void copy_blocks_to(dealii::FullMatrix<double> &matrix) const;

    unsigned int                             n_nodes;
    std::vector<std::array<unsigned int, 3>> dof; // dof[a][c]: the cell DoF of e_c phi_a
    // Per quadrature point: g_a and tau g_a; per node: A_a (c, d, l) flattened.
    std::vector<dealii::Tensor<1, 3>>   g, tau_g;
    std::vector<std::array<double, 27>> A;
    // K's 3x3 blocks (a, b <= a), block (a, b) at 9 (a n_nodes + b).
    std::vector<double> block;
  };
} // namespace softchain::fem
