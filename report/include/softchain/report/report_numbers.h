#pragma once
// Numbers as the report shows them: the median of measured values and a
// value to a few significant digits.
#include <string>
#include <vector>

namespace softchain::report
{
  // Median of `values` (NaN when empty).
  double median(std::vector<double> values);
  // `value` with `digits` significant digits.
  std::string fmt(double value, int digits = 3);
} // namespace softchain::report
