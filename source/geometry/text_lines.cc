#include <softchain/data/input_error.h>
#include <softchain/geometry/text_lines.h>

#include <filesystem>

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

  std::string TextLines::read_all(const std::string &path, const std::string &kind)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw data::InputError(path + ": cannot open the " + kind);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void TextLines::write_all(const std::string &path, const std::string &text, const std::string &kind)
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out)
      throw data::InputError(path + ": cannot write the " + kind);
  }

  std::string TextLines::beside(const std::string &beside, const std::string &file)
  {
    const std::filesystem::path p(file);
    if (file.empty() || p.is_absolute())
      return file;
    return (std::filesystem::path(beside).parent_path() / p).string();
  }

  void TextLines::fail(const std::string &what) const
  {
    throw data::InputError(path_ + ":" + std::to_string(number_) + ": " + what);
  }
} // namespace softchain::geometry
