// BoundingBoxFrame (M1): edge vectors between deformed face centroids of the
// slab's reference bounding box, Gram-Schmidt from the long axis x.
#include <softchain/data/input_error.h>
#include <softchain/reduction/bounding_box_frame.h>
#include <softchain/data/vector_of_point.h>

namespace softchain::reduction
{
  namespace
  {
    // Edge vector along reference axis k: deformed centroid of the nodes on
    // the max-k face minus that of the nodes on the min-k face. A node is on
    // a face when its reference coordinate is within 1e-9 of the box's
    // diagonal from it (round-off of mesh coordinates, far below any node
    // spacing).
    Eigen::Vector3d edge_vector(const SlabSelection &slab, const std::vector<data::Point3> &X,
                                const std::vector<data::Point3> &x, int k)
    {
      const auto  &box       = slab.reference_box();
      const double tolerance = 1e-9 * box.diagonal().norm();
      Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
      int             n_low = 0, n_high = 0;
      for (const auto j : slab.nodes())
        {
          if (X[j][k] <= box.min()(k) + tolerance)
            {
              low += data::vector_of(x[j]);
              ++n_low;
            }
          if (X[j][k] >= box.max()(k) - tolerance)
            {
              high += data::vector_of(x[j]);
              ++n_high;
            }
        }
      if (n_low == 0 || n_high == 0)
        return Eigen::Vector3d::Zero();
      return high / n_high - low / n_low;
    }
  } // namespace

  BoundingBoxFrame::BoundingBoxFrame(const SlabSelection &slab, const std::vector<data::Point3> &X,
                                     const std::vector<data::Point3> &x, const std::string &sample)
  {
    const auto fail = [&](const std::string &what) {
      throw data::InputError(slab.label() + ", sample '" + sample + "': M1 frame: " + what);
    };
    const Eigen::Vector3d ex = edge_vector(slab, X, x, 0);
    const Eigen::Vector3d ey = edge_vector(slab, X, x, 1);
    const Eigen::Vector3d ez = edge_vector(slab, X, x, 2);
    // A box edge that collapses to round-off of the coordinates (1e-12 of
    // the deformed slab size) has no direction.
    const double smallest = 1e-12 * (ex.norm() + ey.norm() + ez.norm());
    if (ex.norm() <= smallest)
      fail("the x edge of the bounding box collapsed");
    const Eigen::Vector3d x_hat = ex.normalized();
    const Eigen::Vector3d y_in  = ey - ey.dot(x_hat) * x_hat;
    if (y_in.norm() <= smallest)
      fail("the y edge of the bounding box is parallel to the x edge");
    const Eigen::Vector3d y_hat = y_in.normalized();
    const Eigen::Vector3d z_hat = x_hat.cross(y_hat);
    if (!(ez.dot(z_hat) > 0))
      fail("the z edge points against x cross y (reflected slab)");
    R_.col(0) = x_hat;
    R_.col(1) = y_hat;
    R_.col(2) = z_hat;
  }
} // namespace softchain::reduction
