#include <softchain/data/text.h>

namespace softchain::data
{
  std::string trim(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos)
      return "";
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
  }
} // namespace softchain::data
