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

    PiecewiseLinear shifted(const PiecewiseLinear &table, const double offset)
    {
      std::vector<double> values = table.values();
      for (double &v : values)
        v += offset;
      return PiecewiseLinear(table.abscissae(), values);
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

  KinematicChain LinkGeometry::at(const double pressure, const KinematicChain &reference) const
  {
    if (reference.n_joints() != n_joints())
      throw std::invalid_argument("LinkGeometry: the chain has another number of joints");
    std::vector<Eigen::Vector3d> joints(joints_.size());
    for (std::size_t i = 0; i < joints_.size(); ++i)
      joints[i] = evaluate(joints_[i], pressure);
    const Eigen::Vector3d rotation = evaluate(tip_frame_, pressure);
    const double          angle    = rotation.norm();
    const Eigen::Matrix3d tip_frame =
      angle > 0.0 ? Eigen::Matrix3d(Eigen::AngleAxisd(angle, rotation / angle)) : Eigen::Matrix3d::Identity();
    return reference.with_link_geometry(std::move(joints), evaluate(tip_, pressure), tip_frame);
  }

  LinkGeometry LinkGeometry::with_twist_joints(const std::vector<Eigen::Vector3d> &offsets) const
  {
    if (offsets.size() != joints_.size())
      throw std::invalid_argument("LinkGeometry: one twist offset per joint needed");
    std::vector<PointInPressure> pairs;
    for (std::size_t i = 0; i < joints_.size(); ++i)
      {
        PointInPressure twist = joints_[i];
        for (int c = 0; c < 3; ++c)
          twist[c] = shifted(joints_[i][c], offsets[i](c));
        pairs.push_back(std::move(twist));
        pairs.push_back(joints_[i]);
      }
    return LinkGeometry(std::move(pairs), tip_, tip_frame_);
  }
} // namespace softchain::chain
