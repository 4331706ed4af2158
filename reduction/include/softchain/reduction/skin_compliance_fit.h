#pragma once
// SkinComplianceFit: the compliance c_s(p) of the finger's sections under a
// force on the palm (the chain tier's skin, ChainContact): how far the palm
// gives towards the cavity, relative to the link that carries it, per newton
// pressing along its normal. A pneumatic finger's palm is a plate spanning
// the cavity, which the gas does not stiffen under pressure control: pressed
// by an obstacle it gives before the joints turn, and a chain of rigid
// sections presses too hard where the contact is concentrated (a grasp).
//
// Per skin sample s (forces f_k at palm points X_k along the palm's inward
// normal, SampleSet's 'palm F') at pressure p, with the pressure state P at p:
// each point lies on link b (the last joint at or before X_k along x). The
// chain of P's links turned by s's own link rotations carries it to x_k
// (SampleReduction::carried_from; its deformed position in P and in s taken
// through the body's cells, BodySamples); what the joints do not carry
// along the palm's inward normal d_b = R_b e_y is the skin's give
//   delta_k = d_b . (y_k(s) - x_k).
// The chain moves a link's whole skin by s_b = c_s F_b, F_b = sum_k f_k . d_b, so
// per sample delta = mean_k delta_k and F = sum_k f_k . d_k, and per pressure
// the least-squares value
//   c_s(p) = max(0, sum_s delta_s F_s / sum_s F_s^2)
// (a palm does not give against the force; a negative value becomes 0 with a
// warning). Samples of `Skin roles`, pressure states of `Pressure roles`
// (the rest configuration at p = 0), as LinkComplianceFit.
//
// SkinDirection::shear fits the same way along the link's axis e_b = R_b e_x
// instead of d_b: c_t(p), how far the palm slides towards the tip, relative
// to its link, per newton of force along the palm ('shear F' skin samples).
// A section sheared by a sticking contact gives like that (the silicone
// between the palm and the fabric layer shears), and the chain puts c_t in
// series with each sticking point's tangential penalty (CoulombFriction).
// Each fit takes the skin samples whose forces lie mostly along its own
// direction (|F| at least half the forces' sum of magnitudes); the others
// are the other fit's.
#include <softchain/data/actuation_database.h>
#include <softchain/data/csv_table.h>
#include <softchain/reduction/body_samples.h>
#include <softchain/reduction/joint_geometry.h>
#include <softchain/reduction/reduction_parameters.h>
#include <softchain/reduction/sample_reduction.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace softchain::reduction
{
  // Along which of a link's axes a fit measures the palm's give.
  enum class SkinDirection
  {
    normal, // the palm's inward normal R_b e_y: c_s
    shear   // the finger's axis R_b e_x, along the palm: c_t
  };

  struct SkinComplianceAtPressure
  {
    double pressure;   // Pa
    double compliance; // c_s, m/N
    int    samples;    // skin samples fitted
  };

  class SkinComplianceFit
  {
  public:
    SkinComplianceFit() = default;
    // `reduced[i]` is `records[i]` reduced; `rest` the rest configuration.
    SkinComplianceFit(const std::vector<data::SampleRecord> &records,
                      const std::vector<SampleReduction> &reduced, const SampleReduction &rest,
                      const JointGeometry &geometry, const data::MeshRecord &mesh,
                      const ReductionParameters &parameters, SkinDirection direction = SkinDirection::normal);

    const std::vector<SkinComplianceAtPressure> &values() const { return values_; }
    // pressure,compliance,samples, by increasing pressure.
    data::CsvTable table() const;
    // Warnings about skipped samples and pressures (empty if none).
    const std::vector<std::string> &warnings() const { return warnings_; }

  private:
    // A pressure state: its deformed nodes and its reduction.
    struct State
    {
      const std::vector<data::Point3> *x;
      const SampleReduction           *reduced;
    };
    std::optional<std::pair<double, double>> measured_give(const data::SampleRecord &s,
                                                           const SampleReduction &reduced, const State &state,
                                                           const JointGeometry &geometry,
                                                           const BodySamples &body);
    // Whether sample `s`'s forces lie mostly along this fit's direction.
    bool along_direction(const data::SampleRecord &s, const SampleReduction &reduced,
                         const JointGeometry &geometry) const;
    std::string name() const { return axis_ == 1 ? "skin compliance" : "skin shear compliance"; }

    int                                   axis_; // of the link's frame: 1 normal, 0 shear

    std::vector<SkinComplianceAtPressure> values_;
    std::vector<std::string>              warnings_;
  };
} // namespace softchain::reduction
