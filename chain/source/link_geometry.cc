// LinkGeometry: the link geometry U(p) interpolated in pressure.
#include <softchain/chain/link_geometry.h>

#include <Eigen/Geometry>

#include <stdexcept>

namespace softchain::chain
{
  namespace
  {
    Eigen::Vector3d evaluate(const LinkGeometry::PointInPressure &point, const double pressure)
    {
      return {point[0](pressure), point[1](pressure), point[2](pressure)};
    }
  } // namespace

  LinkGeometry::LinkGeometry(std::vector<PointInPressure> joints, PointInPressure tip,
                             PointInPressure tip_frame)
    : joints_(std::move(joints))
    , tip_(std::move(tip))
    , tip_frame_(std::move(tip_frame))
  {
    if (joints_.empty())
      throw std::invalid_argument("LinkGeometry: no joints");
  }

  std::vector<double> LinkGeometry::table_pressures() const
  {
    std::vector<double> pressures;
    const auto          merge = [&](const PointInPressure &point) {
      for (const PiecewiseLinear &coordinate : point)
        merge_abscissae(coordinate.abscissae(), pressures);
    };
    for (const PointInPressure &point : joints_)
      merge(point);
    merge(tip_);
    merge(tip_frame_);
    return pressures;
  }

  KinematicChain LinkGeometry::at(const double pressure, const KinematicChain &reference) const
  {
    KinematicChain chain = reference;
    apply(pressure, chain);
    return chain;
  }

  void LinkGeometry::apply(const double pressure, KinematicChain &chain) const
  {
    if (chain.n_joints() != n_joints())
      throw std::invalid_argument("LinkGeometry: the chain has another number of joints");
    const Eigen::Vector3d rotation = evaluate(tip_frame_, pressure);
    const double          angle    = rotation.norm();
    const Eigen::Matrix3d tip_frame =
      angle > 0.0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, rotation / angle)) : Eigen::Matrix3d::Identity();
    chain.assign_link_geometry([&](const int i) { return evaluate(joints_[i], pressure); },
                               evaluate(tip_, pressure), tip_frame);
  }
} // namespace softchain::chain
