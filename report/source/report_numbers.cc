#include <softchain/report/report_numbers.h>

#include <sstream>

namespace softchain::report
{
  std::string fmt(const double value, const int digits)
  {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
  }
} // namespace softchain::report
