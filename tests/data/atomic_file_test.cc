// write_atomically: a writer that fails half way leaves the original file
// as it was and no temporary file behind; a writer that succeeds replaces it.
#include "../../data/source/atomic_file.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "scratch_directory.h"

using softchain::testing::ScratchDirectory;

namespace
{
  std::string content(const std::string &path)
  {
    std::ostringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  }

  std::size_t n_files(const ScratchDirectory &dir)
  {
    return std::distance(std::filesystem::directory_iterator(dir.path()),
                         std::filesystem::directory_iterator());
  }
} // namespace

TEST_CASE("an interrupted atomic write leaves the old file intact")
{
  ScratchDirectory  dir("atomic");
  const std::string path = dir.file("db.h5");
  std::ofstream(path) << "old complete content";
  CHECK_THROWS_AS(softchain::data::write_atomically(path,
                                                    [](const std::string &temporary) {
                                                      std::ofstream(temporary) << "new, half";
                                                      throw std::runtime_error("crash");
                                                    }),
                  std::runtime_error);
  CHECK(content(path) == "old complete content");
  CHECK(n_files(dir) == 1);
  softchain::data::write_atomically(path, [](const std::string &temporary) {
    std::ofstream(temporary) << "new complete content";
  });
  CHECK(content(path) == "new complete content");
  CHECK(n_files(dir) == 1);
}
