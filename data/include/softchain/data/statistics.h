#pragma once
// The statistics the tiers and benchmarks report over repeated runs.
#include <vector>

namespace softchain::data
{
  // The median of `values` (the mean of the middle two for an even count);
  // NaN for none. Timings quote medians: robust to the outliers of a
  // shared machine.
  double median(std::vector<double> values);
} // namespace softchain::data
