#pragma once
// The softchain commands (ARCHITECTURE.md, "Command line"). Each returns the
// process exit status: 0 success, 1 bad input, 2 some sample failed.
#include <string>

namespace softchain
{
  int solve_command(const std::string &prm_file);
} // namespace softchain
