// JointGeometry: joints and slabs of the paper's placement and of the
// strain-limiting-layer placement.
#include <softchain/data/input_error.h>
#include <softchain/reduction/joint_geometry.h>

#include <sstream>

namespace softchain::reduction
{
  JointGeometry::JointGeometry(const JointLayout &layout, const data::MeshRecord &mesh,
                               double half_width)
    : placement_(JointPlacement::paper)
    , reference_points_(mesh.X)
  {
    for (int joint = 1; joint <= layout.n_joints(); ++joint)
      {
        slabs_.emplace_back(mesh.X, joint, layout.x(joint), half_width);
        x_joints_.push_back(layout.x(joint));
        reference_centres_.push_back(slabs_.back().reference_centre());
      }
  }

  JointGeometry::JointGeometry(const JointLayout &layout, std::shared_ptr<const BodySamples> body,
                               double layer_height, double half_width)
    : placement_(JointPlacement::strain_limiting_layer)
    , body_(std::move(body))
    , reference_points_(body_->lattice())
  {
    const double z_centre = body_->reference_box().center()(2);
    const double tip      = body_->reference_box().max()(0);
    for (int joint = 1; joint <= layout.n_joints(); ++joint)
      {
        const double x    = layout.x(joint);
        const double next = joint < layout.n_joints() ? layout.x(joint + 1) : tip;
        // b scales with the link's length, so that the shorter last link's
        // slab stays symmetric about its middle for b <= a/2.
        const double scaled = half_width * (next - x) / layout.spacing();
        slabs_.emplace_back(reference_points_, joint, 0.5 * (x + next), scaled);
        x_joints_.push_back(x);
        reference_centres_.emplace_back(x, layer_height, z_centre);
        const auto located = body_->locate(reference_centres_.back());
        if (!located)
          {
            std::ostringstream text;
            text << "joint " << joint << ": its centre (" << x << ", " << layer_height << ", "
                 << z_centre << ") m on the strain-limiting layer lies outside the body "
                 << "(Reduction/Joint height)";
            throw data::InputError(text.str());
          }
        located_centres_.push_back(*located);
      }
  }

  std::vector<data::Point3> JointGeometry::points(const std::vector<data::Point3> &x) const
  {
    return body_ ? body_->deformed_lattice(x) : x;
  }

  Eigen::Vector3d JointGeometry::deformed_centre(std::size_t i, const JointFrames &frames,
                                                 const std::vector<data::Point3> &x) const
  {
    return body_ ? body_->deformed(located_centres_[i], x) : frames[i].centre;
  }

  Eigen::Vector3d JointGeometry::reference_twist_point(std::size_t i) const
  {
    return reference_centres_[i] + Eigen::Vector3d(0, twist_offset_, 0);
  }

  Eigen::Vector3d JointGeometry::deformed_twist_point(std::size_t i, const JointFrames &frames,
                                                      const std::vector<data::Point3> &x) const
  {
    const Eigen::Matrix3d proximal =
      i == 0 ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(frames[i - 1].rotation);
    return deformed_centre(i, frames, x) + proximal * Eigen::Vector3d(0, twist_offset_, 0);
  }

  Eigen::Vector3d JointGeometry::section_normal(std::size_t i, const JointFrames &frames) const
  {
    const Eigen::Vector3d distal = frames[i].rotation.col(0);
    if (placement_ == JointPlacement::paper)
      return distal;
    const Eigen::Vector3d proximal =
      i == 0 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(frames[i - 1].rotation.col(0));
    return (proximal + distal).normalized();
  }
} // namespace softchain::reduction
