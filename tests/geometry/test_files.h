#pragma once
// Paths and small files for the geometry tests (SOFTCHAIN_SOURCE_DIR and
// SOFTCHAIN_BINARY_DIR come from the test target's compile definitions).
#include <softchain/geometry/text_lines.h>

#include <filesystem>
#include <regex>
#include <stdexcept>
#include <utility>
#include <vector>
#include <string>

namespace softchain::geometry::testing
{
  inline std::string source_path(const std::string &relative)
  {
    return std::string(SOFTCHAIN_SOURCE_DIR) + "/" + relative;
  }

  // A fresh (emptied) directory under the build tree.
  inline std::string scratch_directory(const std::string &name)
  {
    const auto path = std::filesystem::path(SOFTCHAIN_BINARY_DIR) / "geometry_test_scratch" / name;
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path.string();
  }

  inline void write_text(const std::string &path, const std::string &text)
  {
    TextLines::write_all(path, text, "test file");
  }

  // A copy of a shipped design with some entries of "Finger design" changed,
  // e.g. {{"Resolution", "0"}}: each "set NAME = ..." line is rewritten.
  inline std::string design_variant(const std::string &design, const std::string &directory,
                                    const std::vector<std::pair<std::string, std::string>> &changes)
  {
    std::string text =
      TextLines::read_all(source_path("parameter_files/" + design + ".prm"), "design file");
    for (const auto &[name, value] : changes)
      {
        const std::regex entry("set " + name + " *=[^#\n]*");
        if (!std::regex_search(text, entry))
          throw std::logic_error(design + ".prm has no entry '" + name + "'");
        text = std::regex_replace(text, entry, "set " + name + " = " + value + " ");
      }
    const std::string path = directory + "/" + design + ".prm";
    write_text(path, text);
    return path;
  }
} // namespace softchain::geometry::testing
