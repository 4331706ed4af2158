// SlabSelection: A_i = { nodes j : |X_j,x - x_i| <= b } and its bounding box.
#include <softchain/reduction/slab_selection.h>

#include <cmath>
#include <sstream>

namespace softchain::reduction
{
  SlabSelection::SlabSelection(const std::vector<data::Point3> &X, int joint, double x_joint,
                               double half_width)
    : joint_(joint)
    , x_joint_(x_joint)
    , half_width_(half_width)
  {
    // Nodes on the planes x_i +- b belong to the slab: b is widened by
    // 1e-9 b, far above the round-off of x_i = (i - 1/2) a and far below
    // any node spacing of a mesh.
    const double reach = half_width * (1 + 1e-9);
    for (std::size_t j = 0; j < X.size(); ++j)
      if (std::abs(X[j][0] - x_joint) <= reach)
        {
          nodes_.push_back(j);
          box_.extend(Eigen::Vector3d(X[j][0], X[j][1], X[j][2]));
        }
  }

  std::string SlabSelection::label() const
  {
    std::ostringstream text;
    text << "joint " << joint_ << " (slab centre x = " << x_joint_ << " m, b = " << half_width_
         << " m)";
    return text.str();
  }
} // namespace softchain::reduction
