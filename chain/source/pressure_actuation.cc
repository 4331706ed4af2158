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

  std::vector<double> PressureActuation::table_pressures() const
  {
    std::vector<double> pressures;
    merge_abscissae(in_pressure_, pressures);
    return pressures;
  }

  Eigen::VectorXd PressureActuation::torque_per_pascal(double pressure) const
  {
    Eigen::VectorXd jp(rest_.size());
    for (Eigen::Index j = 0; j < rest_.size(); ++j)
      jp[j] = per_pascal(j, pressure);
    return jp;
  }

  double PressureActuation::per_pascal(const Eigen::Index j, const double pressure) const
  {
    return depends_on_pressure() ? in_pressure_[j](pressure) : rest_[j];
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
      tau[j] = per_pascal(j, pressure) * pressure;
  }
} // namespace softchain::chain
