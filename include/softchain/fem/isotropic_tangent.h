#pragma once
// IsotropicTangent: the spatial tangent Jc of SoftChain's isotropic strain
// energies in the form they share,
//     Jc = gamma I(x)I + eta S + B(x)I + I(x)B,
// with I the unit tensor, S the symmetric fourth-order identity
// (S_ikdl = (delta_id delta_kl + delta_il delta_kd)/2) and B symmetric:
//   NeoHookeanLog    gamma = lambda, eta = 2 (mu - lambda ln J), B = 0;
//   NeoHookeanSplit  gamma = kappa J^2 - 2/9 tr(mu bbar),
//                    eta   = 2/3 tr(mu bbar) - kappa (J^2 - 1),
//                    B     = -2/3 tau_iso
// (the deviatoric projector P = S - 1/3 I(x)I expanded). Kept as three
// coefficients instead of 81 entries, the tangent's contraction with a
// spatial shape gradient g, which the cell assembly forms per node
// (HyperelasticCell), is closed-form:
//     g^k Jc_ikdl = (gamma g + B g)_i delta_dl + g_i B_dl
//                   + eta/2 (delta_id g_l + delta_il g_d).
#include <deal.II/base/symmetric_tensor.h>

namespace softchain::fem
{
  struct IsotropicTangent
  {
    double                        gamma = 0;
    double                        eta   = 0;
    dealii::SymmetricTensor<2, 3> B;

    // Jc : m for a symmetric m,
    //     gamma tr(m) I + eta m + tr(m) B + (B : m) I.
    dealii::SymmetricTensor<2, 3> apply(const dealii::SymmetricTensor<2, 3> &m) const
    {
      const dealii::SymmetricTensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
      return (gamma * trace(m) + B * m) * I + eta * m + trace(m) * B;
    }
  };
} // namespace softchain::fem
