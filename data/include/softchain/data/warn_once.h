#pragma once
// warn_once: a warning printed once per process. `softchain run` reads the
// same stiffness files in more than one stage (the chain's validation, the
// protocol's torques); each cause is reported the first time, with the count
// of what it covers in the message itself, not again per stage.
#include <ostream>
#include <string>

namespace softchain::data
{
  // Prints `message` and a newline to `out` unless this process has printed
  // the same message before; returns whether it printed.
  bool warn_once(const std::string &message, std::ostream &out);
} // namespace softchain::data
