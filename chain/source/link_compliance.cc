#include <softchain/chain/link_compliance.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  LinkCompliance::LinkCompliance(PiecewiseLinear compliance)
    : compliance_(std::move(compliance))
  {
    for (const double c : compliance_.values())
      if (!(std::isfinite(c) && c >= 0))
        throw std::invalid_argument("LinkCompliance: compliances must be finite and not negative");
  }

  Eigen::Vector3d LinkCompliance::tip_deflection(const ChainLoad          &load,
                                                 const KinematicChain     &reference) const
  {
    const double    x_1    = reference.joint_centre(0).x();
    const double    length = reference.tip().x() - x_1;
    Eigen::Vector3d sum    = Eigen::Vector3d::Zero();
    for (const PointLoad &f : load.point_loads)
      sum += std::clamp((f.reference_point.x() - x_1) / length, 0.0, 1.0) * f.force;
    return at(load.pressure) * sum;
  }
} // namespace softchain::chain
