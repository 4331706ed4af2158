#pragma once
// Base64 (RFC 4648, with '=' padding): how the report embeds PNG and SVG
// images as data: URIs, so that report.html needs no other file.
#include <string>

namespace softchain::report
{
  std::string base64(const std::string &bytes);

  // "data:<mime>;base64,<base64(bytes)>", the src of an <img>.
  std::string data_uri(const std::string &mime, const std::string &bytes);
} // namespace softchain::report
