#pragma once
// How often `what` occurs in `text` (overlapping occurrences counted), for
// tests that check generated files (HTML, SVG, MJCF, logs).
#include <cstddef>
#include <string>

namespace softchain::testing
{
  inline std::size_t occurrences(const std::string &text, const std::string &what)
  {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
      ++n;
    return n;
  }
} // namespace softchain::testing
