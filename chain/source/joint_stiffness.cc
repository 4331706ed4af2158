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

  void JointStiffness::set_in_pressure(int axis, std::vector<PiecewiseLinear> tables)
  {
    if (axis < 0 || axis > 2 || static_cast<int>(tables.size()) != n_joints())
      throw std::invalid_argument("JointStiffness: one k(p) table per joint and axis 0-2 needed");
    in_pressure_[axis] = std::move(tables);
  }

  bool JointStiffness::depends_on_pressure() const
  {
    return !in_pressure_[0].empty() || !in_pressure_[1].empty() || !in_pressure_[2].empty();
  }

  std::vector<double> JointStiffness::table_pressures() const
  {
    std::vector<double> pressures;
    for (const std::vector<PiecewiseLinear> &tables : in_pressure_)
      merge_abscissae(tables, pressures);
    return pressures;
  }

  std::vector<double> JointStiffness::table_pressures(const int axis) const
  {
    std::vector<double> pressures;
    merge_abscissae(in_pressure_[axis], pressures);
    return pressures;
  }

  Eigen::VectorXd JointStiffness::diagonal(double pressure) const
  {
    Eigen::VectorXd k;
    diagonal(pressure, k);
    return k;
  }

  void JointStiffness::diagonal(double pressure, Eigen::VectorXd &k) const
  {
    k.resize(3 * n_joints());
    for (int i = 0; i < n_joints(); ++i)
      for (int axis = 0; axis < 3; ++axis)
        k[3 * i + axis] = in_pressure_[axis].empty() ? per_joint_[i][axis] :
                                                       in_pressure_[axis][i](pressure);
  }
} // namespace softchain::chain
