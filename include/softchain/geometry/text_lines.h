#pragma once
// TextLines: reads a text file line by line and knows where it is, so that
// every complaint about the file is an InputError "FILE:LINE: what"; and the
// whole-file reads and writes of the geometry module.
#include <fstream>
#include <sstream>
#include <string>

namespace softchain::geometry
{
  class TextLines
  {
  public:
    // Throws InputError "PATH: cannot open the KIND" if the file is missing.
    TextLines(const std::string &path, const std::string &kind);

    // The next line (false at the end of the file).
    bool next(std::string &line);
    // The next line as a stream; fails with "unexpected end of file" at the end.
    std::istringstream next_stream();

    [[noreturn]] void fail(const std::string &what) const;

    // The whole file (bytes as they are); InputError "PATH: cannot open the KIND".
    static std::string read_all(const std::string &path, const std::string &kind);
    // Writes `text`, creating missing parent directories; InputError
    // "PATH: cannot write the KIND".
    static void write_all(const std::string &path, const std::string &text, const std::string &kind);
    // `file` named in the file `beside`: relative to its directory (an
    // absolute or empty name as it is), how the .prm's file parameters resolve.
    static std::string beside(const std::string &beside, const std::string &file);

  private:
    std::ifstream in_;
    std::string   path_;
    int           number_ = 0;
  };
} // namespace softchain::geometry
