#include <softchain/data/fabric_hinge.h>

#include <algorithm>

namespace softchain::data
{
  namespace
  {
    Eigen::Vector3d edge_gradient(const double u, const double r) { return {0.0, -u, r}; }
  } // namespace

  Eigen::Vector3d FabricHinge::fibre_torque_per_kappa(const Eigen::Vector3d &d) const
  {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (const double u : {-1.0, 1.0})
      {
        const Eigen::Vector3d w = edge_gradient(u, r);
        g += (std::max(theta_0 + w.dot(d), 0.0) - theta_0) * w;
      }
    return g;
  }

  FabricHinge::Value FabricHinge::evaluate(const Eigen::Vector3d &d) const
  {
    Value v;
    v.energy  = 0.5 * d.dot(k.cwiseProduct(d));
    v.torque  = k.cwiseProduct(d) + kappa * fibre_torque_per_kappa(d);
    v.tangent = k.asDiagonal();
    for (const double u : {-1.0, 1.0})
      {
        const Eigen::Vector3d w       = edge_gradient(u, r);
        const double          stretch = theta_0 + w.dot(d);
        const double          taut    = std::max(stretch, 0.0);
        v.energy += 0.5 * kappa * (taut * taut - theta_0 * theta_0 - 2.0 * theta_0 * w.dot(d));
        if (stretch > 0.0)
          v.tangent += kappa * w * w.transpose();
      }
    return v;
  }
} // namespace softchain::data
