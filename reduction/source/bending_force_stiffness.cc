// BendingForceStiffness: k_phi from in-plane tip force increments over the
// pressure-only state.
#include <softchain/reduction/bending_force_stiffness.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace softchain::reduction
{
  namespace
  {
    constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

    bool has_role(const SampleReduction &sample, const std::vector<std::string> &roles)
    {
      return std::find(roles.begin(), roles.end(), sample.role()) != roles.end();
    }

    // The pressure-only state at `pressure`: a pressure sample, or the rest
    // (nullptr with `found`) at p = 0.
    const SampleReduction *base_state(const std::vector<SampleReduction> &samples,
                                      const std::vector<std::string> &pressure_roles,
                                      const double pressure, bool &found)
    {
      found = pressure == 0.0;
      if (found)
        return nullptr;
      for (const auto &sample : samples)
        if (has_role(sample, pressure_roles) && sample.pressure() == pressure)
          {
            found = true;
            return &sample;
          }
      return nullptr;
    }
  } // namespace

  BendingForceStiffness::BendingForceStiffness(const std::vector<SampleReduction> &samples,
                                               const std::vector<std::string>     &bending_roles,
                                               const std::vector<std::string>     &pressure_roles,
                                               const double                        threshold)
    : threshold_(threshold)
  {
    for (const auto &sample : samples)
      {
        if (!has_role(sample, bending_roles))
          continue;
        bool                   found = false;
        const SampleReduction *base  = base_state(samples, pressure_roles, sample.pressure(), found);
        if (!found)
          {
            ++n_without_base_;
            continue;
          }
        Increment increment{sample.pressure(), sample.force_norm(), {}, {}};
        for (std::size_t j = 0; j < sample.joints().size(); ++j)
          {
            const JointResult &loaded = sample.joints()[j];
            increment.angle.push_back(loaded.angles.phi - (base ? base->joints()[j].free_angles.phi : 0.0));
            increment.torque.push_back(loaded.torque.z() - (base ? base->joints()[j].torque.z() : 0.0));
          }
        increments_.push_back(increment);
      }
    std::stable_sort(increments_.begin(), increments_.end(), [](const Increment &a, const Increment &b) {
      return a.pressure != b.pressure ? a.pressure < b.pressure : a.force < b.force;
    });
  }

  bool BendingForceStiffness::usable(const Increment &increment, const std::size_t joint) const
  {
    return std::abs(increment.angle[joint]) >= threshold_ && increment.angle[joint] != 0.0;
  }

  double BendingForceStiffness::at_largest_load(const std::size_t joint) const
  {
    for (auto it = increments_.rbegin(); it != increments_.rend(); ++it)
      if (usable(*it, joint))
        return it->torque[joint] / it->angle[joint];
    return no_value;
  }

  double BendingForceStiffness::fit_over(const std::vector<const Increment *> &increments,
                                         const std::size_t                    joint) const
  {
    double sum_tau_angle = 0, sum_angle_squared = 0;
    for (const Increment *increment : increments)
      if (usable(*increment, joint))
        {
          sum_tau_angle += increment->torque[joint] * increment->angle[joint];
          sum_angle_squared += increment->angle[joint] * increment->angle[joint];
        }
    return sum_angle_squared > 0 ? sum_tau_angle / sum_angle_squared : no_value;
  }

  double BendingForceStiffness::fit(const std::size_t joint) const
  {
    std::vector<const Increment *> all;
    for (const Increment &increment : increments_)
      all.push_back(&increment);
    return fit_over(all, joint);
  }

  int BendingForceStiffness::n_used(const std::size_t joint) const
  {
    return static_cast<int>(std::count_if(increments_.begin(), increments_.end(),
                                          [&](const Increment &i) { return usable(i, joint); }));
  }

  std::map<double, double> BendingForceStiffness::fit_by_pressure(const std::size_t joint) const
  {
    std::map<double, std::vector<const Increment *>> by_pressure;
    for (const Increment &increment : increments_)
      by_pressure[increment.pressure].push_back(&increment);
    std::map<double, double> k;
    for (const auto &[pressure, group] : by_pressure)
      if (const double value = fit_over(group, joint); !std::isnan(value))
        k[pressure] = value;
    return k;
  }
} // namespace softchain::reduction
