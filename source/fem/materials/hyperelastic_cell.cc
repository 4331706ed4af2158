#include <softchain/fem/finite_element_space.h>
#include <softchain/fem/hyperelastic_cell.h>

#include <algorithm>

namespace softchain::fem
{
  using namespace dealii;

  HyperelasticCell::HyperelasticCell(const FiniteElement<3> &fe)
    : n_nodes(fe.n_dofs_per_cell() / 3)
    , dof(node_dof_table(fe))
    , g{{std::vector<double>(n_nodes), std::vector<double>(n_nodes), std::vector<double>(n_nodes)}}
    , tau_g(n_nodes)
    , A(27 * n_nodes)
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
            const Tensor<1, 3> g_a = fe_values.shape_grad(dof[a][0], q) * F_inv;
            for (unsigned int l = 0; l < 3; ++l)
              g[l][a] = g_a[l];
            tau_g[a] = tau * g_a;
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

  namespace
  {
    // K[9 a + cd][b] += A_a[cd][l] g_b^l for b <= a: the inner loop of the
    // tangent, over b so that it vectorises. On x86-64 it is compiled for
    // AVX2 with FMA too, chosen at run time where the processor has them.
#if defined(__x86_64__)
    __attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
    void
    add_node_blocks(const unsigned int n, const double *A, const double *__restrict gx,
                    const double *__restrict gy, const double *__restrict gz,
                    double *__restrict block)
    {
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int cd = 0; cd < 9; ++cd)
          {
            const double  a0 = A[27 * a + 3 * cd], a1 = A[27 * a + 3 * cd + 1],
                         a2 = A[27 * a + 3 * cd + 2];
            double *const K  = block + (9 * a + cd) * n;
            for (unsigned int b = 0; b <= a; ++b)
              K[b] += a0 * gx[b] + a1 * gy[b] + a2 * gz[b];
          }
    }
  } // namespace

  // The blocks (a, b <= a) of one quadrature point.
  // A_a[i][d][l] = JxW (g_a^k c_ikdl + delta_id (tau g_a)_l), with the
  // contraction of IsotropicTangent:
  //     = v_i delta_dl + g_i (JxW B)_dl + delta_id w_l + h delta_il g_d,
  // v = JxW (gamma g + B g), w = JxW (eta/2 g + tau g), h = JxW eta/2.
  void HyperelasticCell::add_tangent(const IsotropicTangent &c, const double JxW)
  {
    const SymmetricTensor<2, 3> B = JxW * c.B;
    const double                h = 0.5 * JxW * c.eta;
    for (unsigned int a = 0; a < n_nodes; ++a)
      {
        const Tensor<1, 3> g_a({g[0][a], g[1][a], g[2][a]});
        const Tensor<1, 3> v = (JxW * c.gamma) * g_a + B * g_a;
        const Tensor<1, 3> w = h * g_a + JxW * tau_g[a];
        double *const      A_a = &A[27 * a];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int d = 0; d < 3; ++d)
            for (unsigned int l = 0; l < 3; ++l)
              A_a[9 * i + 3 * d + l] = (d == l ? v[i] : 0.0) + g_a[i] * B[d][l] +
                                       (i == d ? w[l] : 0.0) + (i == l ? h * g_a[d] : 0.0);
      }
    add_node_blocks(n_nodes, A.data(), g[0].data(), g[1].data(), g[2].data(), block.data());
  }

  // K[c,a ; d,b] = K[d,b ; c,a]: each block fills its mirror image too.
  void HyperelasticCell::copy_blocks_to(FullMatrix<double> &matrix) const
  {
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int b = 0; b <= a; ++b)
        {
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int d = 0; d < 3; ++d)
              {
                const double K = block[(9 * a + 3 * c + d) * n_nodes + b];
                matrix(dof[a][c], dof[b][d]) = K;
                matrix(dof[b][d], dof[a][c]) = K;
              }
        }
  }
} // namespace softchain::fem
