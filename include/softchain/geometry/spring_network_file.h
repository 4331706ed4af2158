#pragma once
// SpringNetworkFile: the text file of spring networks read by the FEM tier.
//
//   # SoftChain spring network v1
//   network NAME
//   polyline open|closed N
//   x y z            (N lines, metres, reference coordinates)
//   ...              (more polylines, more networks)
//
// Lines starting with '#' after the first are comments; blank lines are
// ignored. Coordinates are written with 17 significant digits, so
// read(write(networks)) reproduces the networks exactly.
#include <softchain/geometry/spring_network.h>

namespace softchain::geometry
{
  class SpringNetworkFile
  {
  public:
    // Throws InputError naming file and line on a malformed file.
    static std::vector<SpringNetwork> read(const std::string &path);
    static void write(const std::string &path, const std::vector<SpringNetwork> &networks);
    static std::string text(const std::vector<SpringNetwork> &networks);
  };
} // namespace softchain::geometry
