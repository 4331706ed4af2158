// JointLayout: n = round(L / a) joints at x_i = (i - 1/2) a.
#include <softchain/data/input_error.h>
#include <softchain/reduction/joint_layout.h>

#include <algorithm>
#include <cmath>

namespace softchain::reduction
{
  JointLayout::JointLayout(const std::vector<data::Point3> &X, double spacing, int n_requested,
                           const std::string &source)
    : spacing_(spacing)
    , n_joints_(n_requested)
  {
    if (X.empty())
      throw data::InputError(source + ": the mesh has no nodes, so no joints");
    const auto [lowest, highest] = std::minmax_element(
      X.begin(), X.end(), [](const data::Point3 &p, const data::Point3 &q) { return p[0] < q[0]; });
    const double length = (*highest)[0] - (*lowest)[0];
    if (n_joints_ == 0)
      n_joints_ = static_cast<int>(std::lround(length / spacing_));
    if (n_joints_ < 1)
      throw data::InputError(source + ": the mesh is " + std::to_string(length) +
                             " m long, no joint fits at spacing a = " + std::to_string(spacing_) +
                             " m (Reduction/Joint spacing)");
  }
} // namespace softchain::reduction
