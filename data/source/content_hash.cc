// Content hashes: 64-bit FNV-1a (Fowler, Noll, Vo) over a canonical text.
#include <softchain/data/content_hash.h>

#include <cstdint>
#include <cstdio>

namespace softchain::data
{
  std::string content_hash(std::string_view text)
  {
    // FNV-1a 64: h = (h XOR byte) * prime, from the offset basis.
    std::uint64_t hash = 14695981039346656037ULL;
    for (const unsigned char c : text)
      {
        hash ^= c;
        hash *= 1099511628211ULL;
      }
    char digits[17];
    std::snprintf(digits, sizeof(digits), "%016llx", static_cast<unsigned long long>(hash));
    return digits;
  }

  std::string canonical(double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", value);
    return text;
  }
} // namespace softchain::data
