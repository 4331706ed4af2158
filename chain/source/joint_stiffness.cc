#include <softchain/chain/joint_stiffness.h>

#include <cmath>
#include <stdexcept>

namespace softchain::chain
{
  JointStiffness::JointStiffness(std::vector<Eigen::Vector3d> per_joint)
    : per_joint_(std::move(per_joint))
  {
    if (per_joint_.empty())
      throw std::invalid_argument("JointStiffness: no joints");
    for (const Eigen::Vector3d &k : per_joint_)
      if (!k.allFinite() || !(k.minCoeff() > 0.0))
        throw std::invalid_argument("JointStiffness: stiffness must be positive and finite");
  }

  void JointStiffness::set_bending_in_pressure(std::vector<PiecewiseLinear> bending_in_pressure)
  {
    if (static_cast<int>(bending_in_pressure.size()) != n_joints())
      throw std::invalid_argument("JointStiffness: one k_phi(p) table per joint needed");
    bending_in_pressure_ = std::move(bending_in_pressure);
  }

  Eigen::VectorXd JointStiffness::diagonal(double pressure) const
  {
    Eigen::VectorXd k(3 * n_joints());
    for (int i = 0; i < n_joints(); ++i)
      {
        k.segment<3>(3 * i) = per_joint_[i];
        if (depends_on_pressure())
          k[3 * i + 2] = bending_in_pressure_[i](pressure);
      }
    return k;
  }
} // namespace softchain::chain
