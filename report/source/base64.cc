#include <softchain/report/base64.h>

#include <algorithm>

namespace softchain::report
{
  std::string base64(const std::string &bytes)
  {
    static const char alphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    encoded.reserve((bytes.size() + 2) / 3 * 4);
    // Three bytes (24 bits) become four 6-bit characters; a last group of
    // one or two bytes is padded with '='.
    for (std::size_t i = 0; i < bytes.size(); i += 3)
      {
        const std::size_t n    = std::min<std::size_t>(3, bytes.size() - i);
        unsigned int      bits = 0;
        for (std::size_t k = 0; k < 3; ++k)
          bits = (bits << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k)
          encoded += k <= n ? alphabet[(bits >> (18 - 6 * k)) & 0x3f] : '=';
      }
    return encoded;
  }

  std::string data_uri(const std::string &mime, const std::string &bytes)
  {
    return "data:" + mime + ";base64," + base64(bytes);
  }
} // namespace softchain::report
