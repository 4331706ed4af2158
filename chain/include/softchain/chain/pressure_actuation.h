#pragma once
// PressureActuation: the pressure term of the paper's joint torques
//   tau = J^T f + J_p p                                   (Sec. III-C)
// J_p (3 entries per joint, torque per pascal about the joint's psi, theta,
// phi axes) comes from the reduction's table: the rest row (p = 0, the
// undeformed cavity) or, optionally, J_p(p) interpolated between the rows
// computed on the deformed cavity at the sampled pressures.
#include <softchain/chain/piecewise_linear.h>

#include <Eigen/Core>
#include <vector>

namespace softchain::chain
{
  class PressureActuation
  {
  public:
    // J_p at rest (3n entries, finite; throws std::invalid_argument otherwise).
    explicit PressureActuation(Eigen::VectorXd rest_torque_per_pascal);

    // Makes entry j of J_p follow torque_per_pascal_in_pressure[j](p).
    void set_torque_in_pressure(std::vector<PiecewiseLinear> torque_per_pascal_in_pressure);

    const Eigen::VectorXd &rest_torque_per_pascal() const { return rest_; }
    bool depends_on_pressure() const { return !in_pressure_.empty(); }

    // The tabulated pressures of the J_p(p) tables (sorted, unique; empty if
    // J_p is the rest one): J_p(p) is linear between consecutive ones.
    std::vector<double> table_pressures() const;

    // J_p(p), N m / Pa.
    Eigen::VectorXd torque_per_pascal(double pressure) const;
    // J_p(p) p.
    Eigen::VectorXd torque(double pressure) const;
    // The same into tau (sized 3n; no allocation).
    void            torque(double pressure, Eigen::VectorXd &tau) const;

  private:
    double per_pascal(Eigen::Index j, double pressure) const;

    Eigen::VectorXd              rest_;
    std::vector<PiecewiseLinear> in_pressure_;
  };
} // namespace softchain::chain
