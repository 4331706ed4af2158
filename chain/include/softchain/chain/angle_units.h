#pragma once
// Radians inside, degrees in reports and messages only (docs/conventions.md, "Units").
#include <cmath>

namespace softchain::chain
{
  constexpr double degrees(double radians) { return radians * 180.0 / M_PI; }
} // namespace softchain::chain
