#pragma once
// ObliqueView: the fixed parallel projection of the report's finger
// pictures. The finger bends in the x-y plane (docs/conventions.md, "Axes": long axis +x,
// fabric at the bottom, bending toward -y about z), so the viewer looks at
// that plane from +z, raised a little above it and turned a little toward
// the tip, which shows the top and the side walls as well as the bending.
#include <Eigen/Core>

namespace softchain::report
{
  class ObliqueView
  {
  public:
    // `toward_viewer`: direction from the finger to the viewer (any length).
    explicit ObliqueView(const Eigen::Vector3d &toward_viewer = Eigen::Vector3d(0.35, 0.45, 1.0));

    // Screen coordinates: right and up, in the model's length unit.
    Eigen::Vector2d project(const Eigen::Vector3d &x) const;
    // Distance toward the viewer: a larger depth is nearer, drawn later.
    double depth(const Eigen::Vector3d &x) const { return toward_viewer_.dot(x); }
    const Eigen::Vector3d &toward_viewer() const { return toward_viewer_; }

  private:
    Eigen::Vector3d toward_viewer_, right_, up_;
  };
} // namespace softchain::report
