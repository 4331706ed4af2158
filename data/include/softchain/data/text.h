#pragma once
// Small text helpers shared by the .prm readers of every tier.
#include <string>

namespace softchain::data
{
  // `s` without leading and trailing blanks (space, tab, carriage return).
  std::string trim(const std::string &s);
} // namespace softchain::data
