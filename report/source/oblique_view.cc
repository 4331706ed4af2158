#include <softchain/report/oblique_view.h>

#include <Eigen/Geometry>

namespace softchain::report
{
  // The screen's up is the world's +y as far as the view allows, so that
  // "down" in a picture is the direction the finger bends to.
  ObliqueView::ObliqueView(const Eigen::Vector3d &toward_viewer)
    : toward_viewer_(toward_viewer.normalized())
    , right_(Eigen::Vector3d::UnitY().cross(toward_viewer_).normalized())
    , up_(toward_viewer_.cross(right_))
  {}

  Eigen::Vector2d ObliqueView::project(const Eigen::Vector3d &x) const
  {
    return {right_.dot(x), up_.dot(x)};
  }
} // namespace softchain::report
