#include <softchain/data/fabric_hinge.h>

#include <algorithm>

namespace softchain::data
{
  namespace
  {
    Eigen::Vector3d edge_gradient(const double u, const double r) { return {0.0, -u, r}; }
  } // namespace

  // The root of e / g + sum_u <theta_0 + e + w_u . d>+ - 2 theta_0, which
  // increases strictly in e: of the four sets of taut edges, the one whose
  // linear root makes exactly those edges taut.
  double FabricHinge::layer_stretch(const Eigen::Vector3d &d) const
  {
    if (layer_give == 0.0)
      return 0.0;
    const double a[2] = {theta_0 + edge_gradient(-1.0, r).dot(d), theta_0 + edge_gradient(1.0, r).dot(d)};
    for (int taut = 0; taut < 4; ++taut)
      {
        double sum = 0.0, count = 0.0;
        for (int u = 0; u < 2; ++u)
          if (taut & (1 << u))
            {
              sum += a[u];
              count += 1.0;
            }
        const double e = (2.0 * theta_0 - sum) / (1.0 / layer_give + count);
        bool         consistent = true;
        for (int u = 0; u < 2; ++u)
          consistent = consistent && ((taut & (1 << u)) ? a[u] + e >= 0.0 : a[u] + e <= 0.0);
        if (consistent)
          return e;
      }
    return 0.0; // not reached: one set is always consistent
  }

  Eigen::Vector3d FabricHinge::fibre_torque_per_kappa(const Eigen::Vector3d &d) const
  {
    return fibre_torque_per_kappa(d, layer_stretch(d));
  }

  Eigen::Vector3d FabricHinge::fibre_torque_per_kappa(const Eigen::Vector3d &d, const double e) const
  {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (const double u : {-1.0, 1.0})
      {
        const Eigen::Vector3d w = edge_gradient(u, r);
        g += (std::max(theta_0 + e + w.dot(d), 0.0) - theta_0) * w;
      }
    return g;
  }

  FabricHinge::Value FabricHinge::evaluate(const Eigen::Vector3d &d) const
  {
    const double e = layer_stretch(d);
    Value        v;
    v.energy  = 0.5 * d.dot(k.cwiseProduct(d));
    v.torque  = k.cwiseProduct(d) + kappa * fibre_torque_per_kappa(d, e);
    v.tangent = k.asDiagonal();
    if (layer_give > 0.0)
      v.energy += kappa * (0.5 * e * e / layer_give - 2.0 * theta_0 * e);
    Eigen::Vector3d taut_sum   = Eigen::Vector3d::Zero();
    double          taut_count = 0.0;
    for (const double u : {-1.0, 1.0})
      {
        const Eigen::Vector3d w       = edge_gradient(u, r);
        const double          stretch = theta_0 + e + w.dot(d);
        const double          taut    = std::max(stretch, 0.0);
        v.energy += 0.5 * kappa * (taut * taut - theta_0 * theta_0 - 2.0 * theta_0 * w.dot(d));
        if (stretch > 0.0)
          {
            v.tangent += kappa * w * w.transpose();
            taut_sum += w;
            taut_count += 1.0;
          }
      }
    if (layer_give > 0.0)
      v.tangent -= kappa * taut_sum * taut_sum.transpose() / (1.0 / layer_give + taut_count);
    return v;
  }
} // namespace softchain::data
