#pragma once
// Atomic replacement of a file: the new content is written to a temporary
// file in the same directory, fsync'ed and renamed over the original (then
// the directory is fsync'ed), so readers and crashes see either the old or
// the new complete file.
#include <functional>
#include <string>

namespace softchain::data
{
  // Calls write(temporary) and commits the temporary file over `path`; the
  // temporary file is removed if anything throws.
  void write_atomically(const std::string                              &path,
                        const std::function<void(const std::string &)> &write);

  // Removes the temporaries write_atomically(path, ...) leaves when a writer
  // is killed in it (<path>.tmp<pid>); only the one writer of `path` may.
  void remove_temporaries_of(const std::string &path);

  // fsyncs a directory, which makes the creation, renaming or removal of its
  // entries durable.
  void sync_directory(const std::string &directory);
} // namespace softchain::data
