#pragma once
// PressureSnapshot: which state of the finger the report draws for a
// requested pressure. 0 Pa is the reference mesh; otherwise the converged
// pressure-only sample (no point forces) nearest to the request. A sweep may
// have none at the request (P10 stops at a limit point at 59.7 kPa, so it
// has nothing at 80 kPa): then the nearest one is shown and the caption says
// so, naming the failed pressure-only samples in between.
#include <softchain/data/actuation_database.h>

#include <string>
#include <vector>

namespace softchain::report
{
  struct PressureSnapshot
  {
    double                    requested = 0; // Pa
    double                    pressure  = 0; // Pa, of the state shown
    std::string               sample;        // id; empty for the reference mesh
    std::vector<data::Point3> x;             // node positions shown
    std::string               caption;
    bool                      at_request = true; // pressure is the requested one
  };

  // One snapshot per entry of `requested` (Pa), from the samples of a
  // database whose reference positions are `reference`.
  std::vector<PressureSnapshot> pressure_snapshots(const std::vector<data::Point3>     &reference,
                                                   const std::vector<data::SampleRecord> &samples,
                                                   const std::vector<double> &requested);
} // namespace softchain::report
