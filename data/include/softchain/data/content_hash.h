#pragma once
// Content hashes that key the caches (meshes, database samples): 64-bit FNV-1a
// over a canonical text, printed as 16 hex digits. Doubles enter the text with
// 17 significant digits so that equal values give equal keys.
#include <string>
#include <string_view>

namespace softchain::data
{
  std::string content_hash(std::string_view text);

  // A double in the canonical form used inside hashed texts ("%.17g").
  std::string canonical(double value);
} // namespace softchain::data
