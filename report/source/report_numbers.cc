#include <softchain/report/report_numbers.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softchain::report
{
  double median(std::vector<double> values)
  {
    if (values.empty())
      return NAN;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  }

  std::string fmt(const double value, const int digits)
  {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
  }
} // namespace softchain::report
