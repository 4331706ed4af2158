#pragma once
// SampleDirectory: where a database keeps its samples, one HDF5 file per
// sample, `<database>.samples/<id>.h5` (layout in actuation_database.h).
// A sample file is written to a temporary name in the directory, fsync'ed
// and renamed into place (atomic_file.h), so the directory holds complete
// sample files and, after a crash, at most some temporaries, which are not
// samples and are removed by the next writer.
#include <string>
#include <vector>

namespace softchain::data
{
  class SampleDirectory
  {
  public:
    explicit SampleDirectory(const std::string &database_path);

    const std::string &path() const { return path_; }
    std::string        file_of(const std::string &id) const;
    bool               exists() const;

    // Ids of the complete sample files (names ending in ".h5"), sorted;
    // none if the directory does not exist.
    std::vector<std::string> ids() const;

    // Creates the directory (if missing) and makes its entry durable.
    void create() const;
    // Removes temporaries left by stores that were interrupted; only the
    // writer holding the database's WriterLock may call this.
    void remove_leftovers() const;
    // Renames the directory to the sample directory of `database_path`,
    // replacing one left there before.
    void move_to(const std::string &database_path) const;

  private:
    std::string path_;
  };
} // namespace softchain::data
