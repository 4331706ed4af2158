#pragma once
// Sends one standard stream (std::cout, std::cerr) into another stream while
// it lives, for tests that check what a function prints or warns.
#include <ostream>
#include <streambuf>

namespace softchain::testing
{
  class StreamRedirect
  {
  public:
    StreamRedirect(std::ostream &from, std::ostream &to)
      : from_(from)
      , old_(from.rdbuf(to.rdbuf()))
    {}
    ~StreamRedirect() { from_.rdbuf(old_); }
    StreamRedirect(const StreamRedirect &)            = delete;
    StreamRedirect &operator=(const StreamRedirect &) = delete;

  private:
    std::ostream   &from_;
    std::streambuf *old_;
  };
} // namespace softchain::testing
