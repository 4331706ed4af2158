// ForceIncrementStiffness: k about one axis from force increments over the
// pressure-only state at the same pressure.
#include <softchain/reduction/force_increment_stiffness.h>
#include <softchain/reduction/stiffness_extraction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace softchain::reduction
{
  namespace
  {
    constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

  } // namespace

  const SampleReduction *pressure_state(const std::vector<SampleReduction> &samples,
                                        const std::vector<std::string>     &pressure_roles,
                                        const double pressure, bool &found)
  {
    found = pressure == 0.0;
    if (found)
      return nullptr;
    for (const auto &sample : samples)
      if (sample.has_role(pressure_roles) && sample.pressure() == pressure)
        {
          found = true;
          return &sample;
        }
    return nullptr;
  }

  ForceIncrementStiffness::ForceIncrementStiffness(const std::vector<SampleReduction> &samples,
                                                   const std::vector<std::string> &force_roles,
                                                   const std::vector<std::string> &pressure_roles,
                                                   const int axis, const double threshold,
                                                   const int smallest_loads)
    : threshold_(threshold)
    , smallest_loads_(smallest_loads)
  {
    for (const auto &sample : samples)
      {
        if (!sample.has_role(force_roles))
          continue;
        bool                   found = false;
        const SampleReduction *base  = pressure_state(samples, pressure_roles, sample.pressure(), found);
        if (!found)
          {
            ++n_without_base_;
            continue;
          }
        Increment increment{sample.pressure(), sample.force_norm(), {}, {}, {}};
        for (std::size_t j = 0; j < sample.joints().size(); ++j)
          {
            const JointResult &loaded = sample.joints()[j];
            const double base_angle   = base ? angle_about(base->joints()[j].free_angles, axis) : 0.0;
            double       d_tau[3];
            for (int a = 0; a < 3; ++a)
              d_tau[a] = loaded.torque(a) - (base ? base->joints()[j].torque(a) : 0.0);
            const double norm = std::sqrt(d_tau[0] * d_tau[0] + d_tau[1] * d_tau[1] + d_tau[2] * d_tau[2]);
            increment.angle.push_back(angle_about(loaded.angles, axis) - base_angle);
            increment.torque.push_back(d_tau[axis]);
            increment.share.push_back(norm > 0 ? std::abs(d_tau[axis]) / norm : 0.0);
          }
        increments_.push_back(increment);
      }
    std::stable_sort(increments_.begin(), increments_.end(), [](const Increment &a, const Increment &b) {
      return a.pressure != b.pressure ? a.pressure < b.pressure : a.force < b.force;
    });
  }

  bool ForceIncrementStiffness::usable(const Increment &increment, const std::size_t joint) const
  {
    return std::abs(increment.angle[joint]) >= threshold_ && increment.angle[joint] != 0.0 &&
           increment.share[joint] >= min_share;
  }

  double ForceIncrementStiffness::at_largest_load(const std::size_t joint) const
  {
    for (auto it = increments_.rbegin(); it != increments_.rend(); ++it)
      if (usable(*it, joint))
        return it->torque[joint] / it->angle[joint];
    return no_value;
  }

  double ForceIncrementStiffness::fit_over(const std::vector<const Increment *> &increments,
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

  double ForceIncrementStiffness::fit(const std::size_t joint) const
  {
    std::vector<const Increment *> all;
    for (const Increment &increment : increments_)
      all.push_back(&increment);
    return fit_over(all, joint);
  }

  int ForceIncrementStiffness::n_used(const std::size_t joint) const
  {
    return static_cast<int>(std::count_if(increments_.begin(), increments_.end(),
                                          [&](const Increment &i) { return usable(i, joint); }));
  }

  std::map<double, double> ForceIncrementStiffness::fit_by_pressure(const std::size_t joint) const
  {
    // increments_ is sorted by force within a pressure: the first usable
    // ones are the lightest.
    std::map<double, std::vector<const Increment *>> by_pressure;
    for (const Increment &increment : increments_)
      {
        auto &group = by_pressure[increment.pressure];
        if (usable(increment, joint) &&
            (smallest_loads_ == 0 || static_cast<int>(group.size()) < smallest_loads_))
          group.push_back(&increment);
      }
    std::map<double, double> k;
    for (const auto &[pressure, group] : by_pressure)
      k[pressure] = fit_over(group, joint);
    return k;
  }
} // namespace softchain::reduction
