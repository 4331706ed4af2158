// SampleDirectory: listing, creating, cleaning and moving `<database>.samples`.
#include "sample_directory.h"

#include "atomic_file.h"

#include <algorithm>
#include <filesystem>

namespace softchain::data
{
  namespace
  {
    namespace fs = std::filesystem;

    const std::string sample_extension = ".h5";

    bool is_sample_file(const fs::directory_entry &entry)
    {
      return entry.is_regular_file() && entry.path().extension() == sample_extension;
    }

    // write_atomically's temporary of a sample file: "<id>.h5.tmp<pid>".
    bool is_temporary(const fs::directory_entry &entry)
    {
      return entry.path().filename().string().find(sample_extension + ".tmp") != std::string::npos;
    }
  } // namespace

  SampleDirectory::SampleDirectory(const std::string &database_path)
    : path_(database_path + ".samples")
  {}

  std::string SampleDirectory::file_of(const std::string &id) const
  {
    return path_ + "/" + id + sample_extension;
  }

  bool SampleDirectory::exists() const
  {
    return fs::is_directory(path_);
  }

  std::vector<std::string> SampleDirectory::ids() const
  {
    std::vector<std::string> ids;
    if (!exists())
      return ids;
    for (const auto &entry : fs::directory_iterator(path_))
      if (is_sample_file(entry))
        ids.push_back(entry.path().stem().string());
    std::sort(ids.begin(), ids.end());
    return ids;
  }

  void SampleDirectory::create() const
  {
    if (fs::create_directory(path_))
      sync_directory(fs::absolute(path_).parent_path().string());
  }

  void SampleDirectory::remove_leftovers() const
  {
    if (!exists())
      return;
    for (const auto &entry : fs::directory_iterator(path_))
      if (is_temporary(entry))
        fs::remove(entry.path());
  }

  void SampleDirectory::move_to(const std::string &database_path) const
  {
    const SampleDirectory target(database_path);
    fs::remove_all(target.path_); // as a renamed file replaces its target
    fs::rename(path_, target.path_);
    sync_directory(fs::absolute(path_).parent_path().string());
  }
} // namespace softchain::data
