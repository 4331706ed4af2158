#pragma once
// WriterLock: the one writer of a database. An advisory lock (flock) on the
// file `<database>.lock` beside the database, held from the moment a process
// starts writing until it lets go of the database, so that a second writer
// (another process, or a second ActuationDatabase in the same process: flock
// locks belong to an open file, not to a process) is refused with a clear
// error instead of interleaving its writes. The lock file itself is never
// moved or removed: a lock on a file that can be renamed away would let two
// writers lock two different files under the same name. The kernel drops
// the lock when the process dies, so a killed sweep never leaves it held.
#include <string>

namespace softchain::data
{
  class WriterLock
  {
  public:
    // Throws InputError naming the database if another writer holds it.
    explicit WriterLock(const std::string &database_path);
    WriterLock(const WriterLock &)            = delete;
    WriterLock &operator=(const WriterLock &) = delete;
    ~WriterLock();

  private:
    int file_descriptor_;
  };
} // namespace softchain::data
