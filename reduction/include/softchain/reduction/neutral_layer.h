#pragma once
// NeutralLayer: the height y_n of the finger's layer that does not stretch
// when it bends, where the chain's joints sit (the strain-limiting fabric
// layer of a pneumatic finger).
//
// Measured on the bending samples: along probe lines X(s) = (s, y, z_c) at
// heights y, from the first joint to the last (z_c the middle of the body in
// z, s every a/4), the axial stretch of a sample is
//   lambda(y) = sum_k |x(X_k+1) - x(X_k)| / sum_k |X_k+1 - X_k|
// (x the deformed position, BodySamples). In bending lambda is affine in y;
// fitting lambda_s(y) - 1 = alpha_s + beta_s y over the heights at which the
// whole probe line lies in the body, counted from the bottom (the bottom
// layer below the cavity), the summed lines vanish at
//   y_n = - sum_s alpha_s / sum_s beta_s,
// clamped into the probed heights. Without a bending sample, y_n is the
// height of the body's centroid (the neutral axis of a homogeneous beam).
#include <softchain/data/actuation_database.h>
#include <softchain/reduction/body_samples.h>
#include <softchain/reduction/joint_layout.h>

#include <string>
#include <vector>

namespace softchain::reduction
{
  class NeutralLayer
  {
  public:
    NeutralLayer(const BodySamples &body, const JointLayout &layout,
                 const std::vector<const data::SampleRecord *> &bending_samples);

    double height() const { return height_; }
    // True when measured from samples, false for the centroid fallback.
    bool measured() const { return measured_; }
    // Mean axial stretch lambda(y_n) - 1 over the samples (0 when not measured).
    double residual_stretch() const { return residual_stretch_; }
    // One sentence for the reduction's log.
    std::string description() const;

  private:
    // lambda(y) - 1 of one sample, or NaN when a probe point lies outside the body.
    double stretch(const std::vector<data::Point3> &x, const std::vector<CellPoint> &line) const;
    // The probe line at height y, or empty when a point lies outside the body.
    std::vector<CellPoint> probe_line(double y) const;

    const BodySamples  &body_;
    std::vector<double> s_;
    double              z_centre_;
    double              height_           = 0.0;
    bool                measured_         = false;
    double              residual_stretch_ = 0.0;
    int                 n_samples_        = 0;
  };
} // namespace softchain::reduction
