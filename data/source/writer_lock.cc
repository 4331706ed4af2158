// WriterLock: flock(LOCK_EX | LOCK_NB) on `<database>.lock`.
#include "writer_lock.h"

#include "hdf5_io.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace softchain::data
{
  WriterLock::WriterLock(const std::string &database_path)
  {
    const std::string lock_path = database_path + ".lock";
    file_descriptor_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    hdf5::require(file_descriptor_ >= 0, database_path,
                  "cannot create the lock file '" + lock_path + "'");
    // Not blocking: a sweep waiting silently for another one to finish would
    // look like a hang; the user is told instead.
    if (::flock(file_descriptor_, LOCK_EX | LOCK_NB) != 0)
      {
        ::close(file_descriptor_);
        hdf5::require(false, database_path,
                      "another writer has it open (the lock '" + lock_path +
                        "' is held); wait until that sweep ends or stop it");
      }
  }

  WriterLock::~WriterLock()
  {
    ::close(file_descriptor_); // releases the lock
  }
} // namespace softchain::data
