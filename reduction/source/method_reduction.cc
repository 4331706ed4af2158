// MethodReduction: every sample reduced by one method on one joint
// geometry, the rest configuration and the stiffness.
#include <softchain/data/csv_table.h>
#include <softchain/data/output_files.h>
#include <softchain/reduction/method_reduction.h>

#include <cstdio>

namespace softchain::reduction
{
  namespace
  {
    // The reference configuration as a sample: x = X, no load.
    data::SampleRecord rest_sample(const data::MeshRecord &mesh)
    {
      data::SampleRecord rest;
      rest.id             = "rest";
      rest.actuation.role = "rest";
      rest.x              = mesh.X;
      return rest;
    }

    std::vector<SampleReduction> reduce_all(const std::vector<data::SampleRecord> &samples,
                                            const data::MeshRecord                &mesh,
                                            const JointGeometry                   &geometry,
                                            RotationMethod                         method)
    {
      std::vector<SampleReduction> reduced;
      for (const auto &sample : samples)
        reduced.emplace_back(sample, mesh, geometry, method);
      return reduced;
    }
  } // namespace

  MethodReduction::MethodReduction(RotationMethod method, double fraction,
                                   const ReductionParameters &parameters, JointGeometry geometry,
                                   const data::MeshRecord                &mesh,
                                   const std::vector<data::SampleRecord> &converged_samples)
    : method_(method)
    , fraction_(fraction)
    , geometry_(std::move(geometry))
    , rest_(rest_sample(mesh), mesh, geometry_, method)
    , samples_(reduce_all(converged_samples, mesh, geometry_, method))
    , stiffness_(samples_, parameters, geometry_.n_joints())
    , skin_compliance_(converged_samples, samples_, rest_, geometry_, mesh, parameters)
    , skin_shear_compliance_(converged_samples, samples_, rest_, geometry_, mesh, parameters, SkinDirection::shear)
  {}

  std::string MethodReduction::label() const
  {
    return data::stiffness_label(method_, fraction_);
  }

  std::map<double, const SampleReduction *>
  MethodReduction::pressure_states(const std::vector<std::string> &pressure_roles) const
  {
    std::map<double, const SampleReduction *> states{{0.0, &rest_}};
    for (const SampleReduction &s : samples_)
      if (s.point_forces().empty() && s.has_role(pressure_roles))
        states.emplace(s.pressure(), &s);
    return states;
  }

  const SampleReduction *MethodReduction::state_of(const SampleReduction                           &sample,
                                                   const std::map<double, const SampleReduction *> &states,
                                                   const std::string &kind, const std::string &use,
                                                   std::vector<std::string> &warnings)
  {
    const auto state = states.find(sample.pressure());
    if (state != states.end())
      return state->second;
    warnings.push_back(kind + " sample '" + sample.id() + "' at " + data::CsvTable::cell(sample.pressure()) +
                       " Pa skipped for " + use + ": no pressure sample at that pressure");
    return nullptr;
  }
} // namespace softchain::reduction
