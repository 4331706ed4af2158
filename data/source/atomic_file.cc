// write_atomically: write a temporary file, fsync, rename, fsync directory;
// remove_temporaries_of; sync_directory.
#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace softchain::data
{
  namespace
  {
    namespace fs = std::filesystem;

    // Makes `temporary` durable and puts it in place of `path` atomically.
    void commit(const std::string &temporary, const std::string &path)
    {
      const int  fd     = ::open(temporary.c_str(), O_RDONLY);
      const bool synced = fd >= 0 && ::fsync(fd) == 0;
      // The content is on disk now, so its pages leave the page cache: a
      // sweep writes gigabytes of samples it does not read again, and a page
      // cache filling up with them made each later store slower (twice as
      // slow after 1,000 samples of 100K nodes, benchmarks/database_scale).
      if (synced)
        ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
      if (fd >= 0)
        ::close(fd);
      if (!synced || std::rename(temporary.c_str(), path.c_str()) != 0)
        throw std::runtime_error("cannot sync and rename '" + temporary + "' to '" + path + "'");
      sync_directory(fs::absolute(path).parent_path().string()); // the rename itself
    }
  } // namespace

  void sync_directory(const std::string &directory)
  {
    const int file_descriptor = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (file_descriptor >= 0)
      {
        ::fsync(file_descriptor);
        ::close(file_descriptor);
      }
  }

  void remove_temporaries_of(const std::string &path)
  {
    const fs::path    file(path);
    const std::string prefix    = file.filename().string() + ".tmp";
    const fs::path    directory = file.has_parent_path() ? file.parent_path() : fs::path(".");
    if (!fs::is_directory(directory))
      return;
    for (const auto &entry : fs::directory_iterator(directory))
      if (entry.path().filename().string().rfind(prefix, 0) == 0)
        fs::remove(entry.path());
  }

  void write_atomically(const std::string                              &path,
                        const std::function<void(const std::string &)> &write)
  {
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    try
      {
        write(temporary);
        commit(temporary, path);
      }
    catch (...)
      {
        fs::remove(temporary);
        throw;
      }
  }
} // namespace softchain::data
