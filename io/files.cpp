// SPDX-License-Identifier: GPL-3.0-or-later
// Output files written so that no failure leaves a truncated file behind
// (io/files.h).

#include "io/files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "geometry/error.h"

namespace hrs::io {

namespace {

//! A temporary name beside `path`, unique to this process and call: jobs
//! of one process (the experiments) may write the same file at once.
std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  static std::atomic<long> calls{0};
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += "-";
  name += std::to_string(calls.fetch_add(1));
  return path.parent_path() / name;
}

//! Writes `text` to a new file at `path` and flushes it to disk; false with
//! errno set on failure.
bool write_synced(const std::filesystem::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int saved = n < 0 ? errno : EIO;
      ::close(fd);
      errno = saved;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    return false;
  }
  return ::close(fd) == 0;
}

}  // namespace

void write_files_atomic(const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  std::vector<std::filesystem::path> temporaries;
  auto discard = [&] {
    std::error_code ignored;
    for (const auto& t : temporaries) std::filesystem::remove(t, ignored);
  };
  for (const auto& [path, text] : files) {
    temporaries.push_back(temporary_beside(path));
    if (!write_synced(temporaries.back(), text)) {
      const std::string reason = std::strerror(errno);
      discard();
      throw OutputError(path.string() + ": cannot write file: " + reason);
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temporaries[i].c_str(), files[i].first.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      discard();
      throw OutputError(files[i].first.string() + ": cannot replace file: " + reason);
    }
  }
}

DirectoryLock::DirectoryLock(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / ".hrspace.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputError(path.string() + ": cannot create lock file: " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(dir.string() + ": in use by another hrspace run (it holds " + path.string() +
                       "); wait for it to end or choose another --out");
    throw OutputError(path.string() + ": cannot lock: " + std::strerror(err));
  }
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

void require_writable_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create directory: " + ec.message());
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string() + ": exists and is not a directory");
  }
  const std::filesystem::path probe = temporary_beside(dir / "write-check");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InputError(dir.string() + ": directory is not writable: " + std::strerror(errno));
  }
  ::close(fd);
  std::filesystem::remove(probe, ec);
}

}  // namespace hrs::io
