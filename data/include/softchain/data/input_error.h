#pragma once
// InputError: bad input that the user must fix (a file, a line, a parameter,
// a sample). The command line turns it into exit status 1 and prints what().
#include <stdexcept>
#include <string>

namespace softchain::data
{
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace softchain::data
