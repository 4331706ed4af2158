#include <softchain/data/input_error.h>
#include <softchain/geometry/text_lines.h>

namespace softchain::geometry
{
  TextLines::TextLines(const std::string &path, const std::string &kind)
    : in_(path)
    , path_(path)
  {
    if (!in_)
      throw data::InputError(path + ": cannot open the " + kind);
  }

  bool TextLines::next(std::string &line)
  {
    if (!std::getline(in_, line))
      return false;
    ++number_;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return true;
  }

  std::istringstream TextLines::next_stream()
  {
    std::string line;
    if (!next(line))
      fail("unexpected end of file");
    return std::istringstream(line);
  }

  void TextLines::fail(const std::string &what) const
  {
    throw data::InputError(path_ + ":" + std::to_string(number_) + ": " + what);
  }
} // namespace softchain::geometry
