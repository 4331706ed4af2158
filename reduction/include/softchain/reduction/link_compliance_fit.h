#pragma once
// LinkComplianceFit: the compliance c(p) of the chain's links, in series with
// its joints (the chain tier's LinkCompliance), from the chord samples: tip
// forces that pull along the base-tip chord of the pressure-only state, the
// direction in which the joints alone are stiffest, so that what the links
// give is a large part of the tip's motion there (docs/results.md, "The
// paper's validation experiment on P10").
//
// Per chord sample s at pressure p the links' deflection r_s is the deformed
// tip minus where the chain of the pressure state's links, turned by the
// sample's own rotations, puts it (SampleReduction::link_deflection_from).
// The model (isotropic links, compliance uniform per unit length) says
// r_s = c F_s with F_s = sum_k s_k f_k, s_k the fraction of the length from
// joint 1 to the tip at which force k acts (reference x). Per pressure, the
// non-negative least-squares value
//   c(p) = max(0, sum_s r_s . F_s / sum_s |F_s|^2):
// links cannot give against the force, and a stiff finger's deflection at
// its links lies within what the slabs' rotations resolve (P13 at 40 kPa:
// -3e-6 m/N), so a negative value becomes 0 with a warning. The chord and
// pressure samples are those of the `Chord roles` and `Pressure roles`
// (ReductionParameters). The pressure state is the first pressure sample at
// p (the rest configuration at p = 0); a chord sample without one is skipped
// with a warning.
#include <softchain/data/csv_table.h>
#include <softchain/reduction/method_reduction.h>

#include <string>
#include <vector>

namespace softchain::reduction
{
  struct LinkComplianceAtPressure
  {
    double pressure;      // Pa
    double compliance;    // c, m/N
    int    samples;       // chord samples fitted
    double chord_angle;   // largest angle between F_s and the pressure state's chord, deg
  };

  class LinkComplianceFit
  {
  public:
    LinkComplianceFit(const MethodReduction &reduction, const ReductionParameters &parameters);

    const std::vector<LinkComplianceAtPressure> &values() const { return values_; }
    // pressure,compliance,samples,chord_angle_deg, by increasing pressure.
    data::CsvTable table() const;
    // Warnings about skipped samples and pressures (empty if none).
    const std::vector<std::string> &warnings() const { return warnings_; }

  private:
    std::vector<LinkComplianceAtPressure> values_;
    std::vector<std::string>              warnings_;
  };
} // namespace softchain::reduction
