// JointLayout: n = round(L / a) joints at x_i = (i - 1/2) a.
#include <softchain/data/input_error.h>
#include <softchain/reduction/joint_layout.h>

#include <algorithm>
#include <cmath>
#include <sstream>

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
    // Counted in double first: a spacing mistyped by orders of magnitude
    // would overflow an int.
    const double count = n_joints_ > 0 ? n_joints_ : std::round(length / spacing_);
    if (count >= 1 && count <= max_joints)
      {
        n_joints_ = static_cast<int>(count);
        return;
      }
    std::ostringstream message;
    message << source << ": the mesh is " << length << " m long, so a = " << spacing_
            << " m (Reduction/Joint spacing) gives " << count << " joints";
    if (count < 1)
      message << "; at least one must fit";
    else
      message << ", more than " << max_joints << " (the spacing is in metres)";
    throw data::InputError(message.str());
  }
} // namespace softchain::reduction
