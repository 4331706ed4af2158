#include <softchain/chain/pressure_actuation.h>

#include <stdexcept>

namespace softchain::chain
{
  PressureActuation::PressureActuation(Eigen::VectorXd rest_torque_per_pascal)
    : rest_(std::move(rest_torque_per_pascal))
  {
    if (rest_.size() == 0 || rest_.size() % 3 != 0 || !rest_.allFinite())
      throw std::invalid_argument("PressureActuation: need 3 finite entries per joint");
  }

  void PressureActuation::set_torque_in_pressure(
    std::vector<PiecewiseLinear> torque_per_pascal_in_pressure)
  {
    if (static_cast<Eigen::Index>(torque_per_pascal_in_pressure.size()) != rest_.size())
      throw std::invalid_argument("PressureActuation: one J_p(p) table per joint angle needed");
    in_pressure_ = std::move(torque_per_pascal_in_pressure);
  }

  Eigen::VectorXd PressureActuation::torque(double pressure) const
  {
    Eigen::VectorXd tau;
    torque(pressure, tau);
    return tau;
  }

  void PressureActuation::torque(double pressure, Eigen::VectorXd &tau) const
  {
    tau.resize(rest_.size());
    for (Eigen::Index j = 0; j < rest_.size(); ++j)
      tau[j] = (depends_on_pressure() ? in_pressure_[j](pressure) : rest_[j]) * pressure;
  }
} // namespace softchain::chain
