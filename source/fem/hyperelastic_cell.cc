#include <softchain/fem/finite_element_space.h>
#include <softchain/fem/hyperelastic_cell.h>

#include <algorithm>

namespace softchain::fem
{
  using namespace dealii;

  HyperelasticCell::HyperelasticCell(const FiniteElement<3> &fe)
    : n_nodes(fe.n_dofs_per_cell() / 3)
    , dof(node_dof_table(fe))
    , g(n_nodes)
    , tau_g(n_nodes)
    , A(n_nodes)
    , block(9 * n_nodes * n_nodes)
  {}

  bool HyperelasticCell::assemble(const FEValues<3>               &fe_values,
                                  const std::vector<Tensor<2, 3>> &grad_u,
                                  const HyperelasticMaterial      &material,
                                  const Tensor<1, 3>              &body_force,
                                  FullMatrix<double>              *matrix,
                                  Vector<double>                  &rhs)
  {
    const bool gravity = body_force.norm_square() > 0;
    std::fill(block.begin(), block.end(), 0.0);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const Tensor<2, 3> F = unit_symmetric_tensor<3>() + grad_u[q];
        if (!(determinant(F) > 0))
          return false;
        const Tensor<2, 3>          F_inv = invert(F);
        const SymmetricTensor<2, 3> tau   = material.kirchhoff_stress(F);
        const double                JxW   = fe_values.JxW(q);
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            // g_a = F^-T grad_X phi_a, i.e. the row vector grad_X phi_a F^-1.
            g[a]     = fe_values.shape_grad(dof[a][0], q) * F_inv;
            tau_g[a] = tau * g[a];
            for (unsigned int c = 0; c < 3; ++c)
              rhs(dof[a][c]) -= tau_g[a][c] * JxW;
            if (gravity)
              {
                const double phi_JxW = fe_values.shape_value(dof[a][0], q) * JxW; // phi_a dV0
                for (unsigned int c = 0; c < 3; ++c)
                  rhs(dof[a][c]) += phi_JxW * body_force[c];
              }
          }
        if (matrix)
          add_tangent(material.spatial_tangent(F), JxW);
      }
    if (matrix)
      copy_blocks_to(*matrix);
    return true;
  }

  // The blocks (a, b <= a) of one quadrature point; tau enters through tau_g.
  void HyperelasticCell::add_tangent(const SymmetricTensor<4, 3> &c_tensor, const double JxW)
  {
    double c[3][3][3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int l = 0; l < 3; ++l)
            c[i][k][d][l] = c_tensor[i][k][d][l];
    // A_a[c][d][l] = JxW g_a^k c_ckdl
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int l = 0; l < 3; ++l)
            A[a][9 * i + 3 * d + l] =
              JxW * (g[a][0] * c[i][0][d][l] + g[a][1] * c[i][1][d][l] + g[a][2] * c[i][2][d][l]);
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int b = 0; b <= a; ++b)
        {
          const Tensor<1, 3> &gb        = g[b];
          const double        geometric = JxW * (gb * tau_g[a]);
          double             *K         = &block[9 * (a * n_nodes + b)];
          const double       *Aa        = A[a].data();
          for (unsigned int cd = 0; cd < 9; ++cd)
            K[cd] += Aa[3 * cd] * gb[0] + Aa[3 * cd + 1] * gb[1] + Aa[3 * cd + 2] * gb[2];
          K[0] += geometric;
          K[4] += geometric;
          K[8] += geometric;
        }
  }

  // K[c,a ; d,b] = K[d,b ; c,a]: each block fills its mirror image too.
  void HyperelasticCell::copy_blocks_to(FullMatrix<double> &matrix) const
  {
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int b = 0; b <= a; ++b)
        {
          const double *K = &block[9 * (a * n_nodes + b)];
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int d = 0; d < 3; ++d)
              {
                matrix(dof[a][c], dof[b][d]) = K[3 * c + d];
                matrix(dof[b][d], dof[a][c]) = K[3 * c + d];
              }
        }
  }
} // namespace softchain::fem
