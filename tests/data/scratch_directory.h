#pragma once
// A fresh directory per test case under the system temporary directory,
// removed when the test case ends.
#include <filesystem>
#include <string>

#include <unistd.h>

namespace softchain::testing
{
  class ScratchDirectory
  {
  public:
    explicit ScratchDirectory(const std::string &name)
      : path_(std::filesystem::temp_directory_path() /
              ("softchain_" + name + "_" + std::to_string(::getpid())))
    {
      std::filesystem::remove_all(path_);
      std::filesystem::create_directories(path_);
    }
    ~ScratchDirectory() { std::filesystem::remove_all(path_); }
    std::string file(const std::string &name) const { return (path_ / name).string(); }
    const std::filesystem::path &path() const { return path_; }

  private:
    std::filesystem::path path_;
  };
} // namespace softchain::testing
