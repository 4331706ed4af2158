#include <softchain/data/vector_of_point.h>
#include <softchain/reduction/compliance_sums.h>
#include <softchain/reduction/link_compliance_fit.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace softchain::reduction
{
  namespace
  {
    // F_s = sum_k s_k f_k, s_k the fraction of [x_1, x_T] proximal to force k.
    Eigen::Vector3d effective_force(const SampleReduction &sample, const SampleReduction &rest)
    {
      const double    x_1    = rest.link_geometry().front().x();
      const double    length = rest.link_geometry().back().x() - x_1;
      Eigen::Vector3d F      = Eigen::Vector3d::Zero();
      for (const data::PointForce &f : sample.point_forces())
        F += std::clamp((f.point[0] - x_1) / length, 0.0, 1.0) * data::vector_of(f.force);
      return F;
    }

    double angle_deg(const Eigen::Vector3d &a, const Eigen::Vector3d &b)
    {
      return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
    }
  } // namespace

  LinkComplianceFit::LinkComplianceFit(const MethodReduction &reduction, const ReductionParameters &parameters)
  {
    if (reduction.rest().link_geometry().empty())
      return; // no tip face, no links to measure
    const auto states = reduction.pressure_states(parameters.pressure_roles);
    std::map<double, ComplianceSums> sums;
    std::map<double, double>         angles; // the largest angle to the chord per pressure
    for (const SampleReduction &s : reduction.samples())
      {
        if (!s.has_role(parameters.chord_roles))
          continue;
        const SampleReduction *state =
          MethodReduction::state_of(s, states, "chord", "the links' compliance", warnings_);
        if (!state)
          continue;
        const Eigen::Vector3d F = effective_force(s, reduction.rest());
        sums[s.pressure()].add(s.link_deflection_from(*state).dot(F), F.squaredNorm());
        angles[s.pressure()] = std::max(angles[s.pressure()], angle_deg(F, state->chord()));
      }
    for (const auto &[pressure, sum] : sums)
      {
        const std::string at = data::CsvTable::cell(pressure) + " Pa";
        const auto        c  = sum.compliance("link compliance at " + at + " set to 0: the links' "
                                              "deflection opposes the chord samples' force", warnings_);
        if (c)
          values_.push_back({pressure, *c, sum.samples, angles[pressure]});
        else
          warnings_.push_back("no link compliance at " + at + ": its chord samples carry no force");
      }
  }

  data::CsvTable LinkComplianceFit::table() const
  {
    data::CsvTable table({"pressure", "compliance", "samples", "chord_angle_deg"});
    for (const LinkComplianceAtPressure &v : values_)
      table.add_row(std::vector<double>{v.pressure, v.compliance, double(v.samples), v.chord_angle});
    return table;
  }
} // namespace softchain::reduction
