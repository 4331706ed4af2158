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
// per DoF pair, with
//     A_a[c][d][l] = g_a^k c_ckdl + delta_cd (tau g_a)_l
// formed once per node and quadrature point (the geometric term folded in,
// tau being symmetric), each 3x3 block is K_ab[c][d] += A_a[c][d][l] g_b^l:
// 27 multiply-adds, only for b <= a (K is symmetric). A_a comes from the
// closed-form contraction g_a^k c_ckdl of IsotropicTangent. The loop runs over b,
// with the g_b stored component by component, so that it vectorises.
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
    void add_tangent(const IsotropicTangent &c, double JxW);
    void copy_blocks_to(dealii::FullMatrix<double> &matrix) const;

    unsigned int                             n_nodes;
    std::vector<std::array<unsigned int, 3>> dof; // dof[a][c]: the cell DoF of e_c phi_a
    // Per quadrature point: the components of g_a (g[l][a] = g_a^l), tau g_a
    // and A_a (c, d, l) flattened at 27 a + 9 c + 3 d + l.
    std::array<std::vector<double>, 3> g;
    std::vector<dealii::Tensor<1, 3>>  tau_g;
    std::vector<double>                A;
    // K's 3x3 blocks (a, b <= a): K[c,a ; d,b] at (9 a + 3 c + d) n_nodes + b.
    std::vector<double> block;
  };
} // namespace softchain::fem
