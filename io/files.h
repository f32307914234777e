// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Output files: the one atomic, durable writer of every command (designs,
// experiments, generated rooms), the lock of an output directory and the
// check that an output directory is writable. A write that fails is
// hrs::OutputError (exit 1); a directory that is in use or cannot be made
// is hrs::InputError (exit 2: the user chose it).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hrs::io {

//! Writes each (path, text) to a temporary file in the path's directory,
//! flushed to disk, and only when all of them are written renames them into
//! place: a kill or a full disk leaves the old files or the new ones, never a
//! truncated file. Throws OutputError (the temporary files are removed).
void write_files_atomic(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

//! An advisory lock (flock) on DIR/.hrspace.lock, held while it lives: one
//! writer per output directory. A second `hrspace design` or `experiment`
//! into the same DIR gets InputError (exit 2) naming DIR, at once.
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::filesystem::path& dir);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

//! Creates `dir` if missing and checks that a file can be created in it;
//! InputError naming the directory otherwise. For --out, before any work.
void require_writable_directory(const std::filesystem::path& dir);

}  // namespace hrs::io
