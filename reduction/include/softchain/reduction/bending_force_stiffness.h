#pragma once
// BendingForceStiffness: k_phi of a joint that no pressure sample loads.
// The pressure on a closed cavity has no net moment about a section distal
// to which the whole cavity lies (P10's joint 1, in the solid base fill), so
// the pressure samples give such a joint no torque and no k_phi, yet a tip
// force bends it. The in-plane tip force samples (role bending, made at the
// force sample pressures) measure it: per sample s and joint i, the increment
// over the pressure-only state b at the same pressure (the rest at p = 0),
//   d phi = phi_i(s) - phi_i(b),   d tau = tau_z,i(s) - tau_z,i(b),
// with phi_i(b) the joint's free angle in b (SampleReduction: the rotation it
// passes on there), and k = d tau / d phi: per sample, at the largest load
// (pressure first, then force), and as the least-squares fit
// k = sum(d tau d phi) / sum(d phi^2) over all samples or those at one
// pressure. A bending sample without a pressure-only state at its pressure
// gives nothing (counted); |d phi| below the threshold gives no value.
#include <softchain/reduction/sample_reduction.h>

#include <map>
#include <string>
#include <vector>

namespace softchain::reduction
{
  class BendingForceStiffness
  {
  public:
    BendingForceStiffness(const std::vector<SampleReduction> &samples,
                          const std::vector<std::string>     &bending_roles,
                          const std::vector<std::string>     &pressure_roles,
                          double                              threshold);

    // NaN where no bending sample gives a value.
    double at_largest_load(std::size_t joint) const;
    double fit(std::size_t joint) const;
    int    n_used(std::size_t joint) const;
    // The least-squares k per pressure of the bending samples.
    std::map<double, double> fit_by_pressure(std::size_t joint) const;
    // Bending samples that had no pressure-only state at their pressure.
    int n_without_base() const { return n_without_base_; }

  private:
    struct Increment
    {
      double              pressure;
      double              force;
      std::vector<double> angle;  // d phi per joint
      std::vector<double> torque; // d tau_z per joint
    };
    bool   usable(const Increment &increment, std::size_t joint) const;
    double fit_over(const std::vector<const Increment *> &increments, std::size_t joint) const;

    std::vector<Increment> increments_; // by increasing load
    double                 threshold_;
    int                    n_without_base_ = 0;
  };
} // namespace softchain::reduction
