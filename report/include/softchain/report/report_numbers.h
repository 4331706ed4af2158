#pragma once
// Numbers as the report shows them: the median of measured values
// (data::median) and a value to a few significant digits.
#include <softchain/data/statistics.h>

#include <string>

namespace softchain::report
{
  using data::median;
  // `value` with `digits` significant digits.
  std::string fmt(double value, int digits = 3);
} // namespace softchain::report
