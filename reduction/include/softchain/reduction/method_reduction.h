#pragma once
// MethodReduction: the whole reduction of a database by one rotation method
// and one joint geometry (placement and slab half-width b = fraction * a):
// every converged sample reduced, the rest configuration (for J_p at p = 0)
// and the stiffness.
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/sample_reduction.h>
#include <softchain/reduction/skin_compliance_fit.h>
#include <softchain/reduction/stiffness_extraction.h>

#include <map>
#include <string>
#include <vector>

namespace softchain::reduction
{
  class MethodReduction
  {
  public:
    MethodReduction(RotationMethod method, double fraction, const ReductionParameters &parameters,
                    JointGeometry geometry, const data::MeshRecord &mesh,
                    const std::vector<data::SampleRecord> &converged_samples);

    // "<M>_b<f>a" with f the fraction to 2 decimals, e.g. "M2_b0.50a".
    std::string                         label() const;
    const JointGeometry                &geometry() const { return geometry_; }
    const SampleReduction              &rest() const { return rest_; }
    const std::vector<SampleReduction> &samples() const { return samples_; }
    const StiffnessExtraction          &stiffness() const { return stiffness_; }
    const SkinComplianceFit            &skin_compliance() const { return skin_compliance_; }
    const SkinComplianceFit            &skin_shear_compliance() const { return skin_shear_compliance_; }
    // The pressure state of each pressure: the first sample of `pressure_roles`
    // without point forces at it, the rest configuration at 0.
    std::map<double, const SampleReduction *> pressure_states(const std::vector<std::string> &pressure_roles) const;
    // The state of `states` at `sample`'s pressure, or nullptr after appending
    // "<kind> sample '<id>' at <p> Pa skipped for <use>: no pressure sample at
    // that pressure" to `warnings`.
    static const SampleReduction *state_of(const SampleReduction                           &sample,
                                           const std::map<double, const SampleReduction *> &states,
                                           const std::string &kind, const std::string &use,
                                           std::vector<std::string> &warnings);

  private:
    RotationMethod               method_;
    double                       fraction_;
    JointGeometry                geometry_;
    SampleReduction              rest_;
    std::vector<SampleReduction> samples_;
    StiffnessExtraction          stiffness_;
    SkinComplianceFit            skin_compliance_;       // c_s(p), along the palm's normal
    SkinComplianceFit            skin_shear_compliance_; // c_t(p), along the palm
  };
} // namespace softchain::reduction
