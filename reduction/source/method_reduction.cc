// MethodReduction: slabs for b = fraction * a, every sample reduced by one
// method, the rest configuration and the stiffness.
#include <softchain/reduction/method_reduction.h>

#include <cstdio>

namespace softchain::reduction
{
  namespace
  {
    std::vector<SlabSelection> slabs_of(const JointLayout &layout, const data::MeshRecord &mesh,
                                        double half_width)
    {
      std::vector<SlabSelection> slabs;
      for (int joint = 1; joint <= layout.n_joints(); ++joint)
        slabs.emplace_back(mesh.X, joint, layout.x(joint), half_width);
      return slabs;
    }

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
                                            const std::vector<SlabSelection>      &slabs,
                                            RotationMethod                         method)
    {
      std::vector<SampleReduction> reduced;
      for (const auto &sample : samples)
        reduced.emplace_back(sample, mesh, slabs, method);
      return reduced;
    }
  } // namespace

  MethodReduction::MethodReduction(RotationMethod method, double fraction,
                                   const ReductionParameters &parameters, const JointLayout &layout,
                                   const data::MeshRecord                &mesh,
                                   const std::vector<data::SampleRecord> &converged_samples)
    : method_(method)
    , fraction_(fraction)
    , slabs_(slabs_of(layout, mesh, fraction * layout.spacing()))
    , rest_(rest_sample(mesh), mesh, slabs_, method)
    , samples_(reduce_all(converged_samples, mesh, slabs_, method))
    , stiffness_(samples_, parameters, slabs_.size())
  {}

  std::string MethodReduction::label() const
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%s_b%.2fa", method_name(method_).c_str(), fraction_);
    return text;
  }
} // namespace softchain::reduction
