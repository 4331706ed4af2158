#pragma once
// The softchain commands (docs/conventions.md, "Command line and exit codes").
// Each returns the process exit status: 0 success, 1 bad input, 2 some sample failed.
#include <string>

namespace softchain
{
  int solve_command(const std::string &prm_file);
  // The sample sweep into <output dir>/database.h5 (SampleSweep).
  int sweep_command(const std::string &prm_file);
  // The whole pipeline: sweep, reduction, chain; lists every output file.
  int run_command(const std::string &prm_file);
} // namespace softchain
