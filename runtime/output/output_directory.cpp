// Claiming an output directory: create, probe, lock.
#include "output/output_directory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "output/run_id.hpp"

namespace pd {

namespace {
namespace fs = std::filesystem;

std::string free_space(const std::string& dir) {
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0) return "";
  return fmt::format(" ({:.1f} MB free)",
                     static_cast<double>(s.f_bavail) * static_cast<double>(s.f_frsize) / 1e6);
}

// Creates, fills and removes a probe file: a full disk shows up as a failed write (the
// probe is a few kilobytes and fsync'd, so a filesystem that delays allocation reports it too).
void probe(const std::string& dir) {
  const std::string path = fmt::format("{}/.pd.probe.{}", dir, run_id());
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0)
    throw OutputDirectoryError(
        fmt::format("output directory {}: cannot create a file in it: {}", dir, std::strerror(errno)));
  const std::string block(4096, 'p');
  std::size_t written = 0;
  int err = 0;
  while (written < block.size() && err == 0) {  // a short write is followed by the one that reports why
    const ssize_t n = ::write(fd, block.data() + written, block.size() - written);
    if (n < 0 && errno != EINTR) err = errno;
    if (n > 0) written += static_cast<std::size_t>(n);
  }
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  const bool ok = err == 0;
  ::close(fd);
  ::unlink(path.c_str());
  if (!ok)
    throw OutputDirectoryError(fmt::format("output directory {}: cannot write to it: {}{}", dir,
                                           std::strerror(err), free_space(dir)));
}
}  // namespace

OutputDirectoryClaim::OutputDirectoryClaim(const std::string& directory) {
  const std::string dir = directory.empty() ? "." : directory;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw OutputDirectoryError(fmt::format("output directory {}: exists and is not a directory", dir));
  directory_ = dir;
  created_ = fs::create_directories(dir, ec);
  if (ec)
    throw OutputDirectoryError(fmt::format("output directory {}: cannot create it: {}", dir, ec.message()));
  try {
    probe(dir);
  } catch (...) {
    if (created_) fs::remove(dir, ec);
    throw;
  }
  lock_path_ = dir + "/.pd.lock";
  // Lock, then check the lock file is still the one at the path: a run that finished
  // between our open and our flock has unlinked it, and a third run may lock a new one.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw OutputDirectoryError(
          fmt::format("{}: cannot create the lock file: {}", lock_path_, std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      char owner[64] = {};
      const ssize_t n = ::pread(fd_, owner, sizeof owner - 1, 0);
      ::close(fd_);
      fd_ = -1;
      if (err != EWOULDBLOCK)
        throw OutputDirectoryError(fmt::format("{}: cannot lock: {}", lock_path_, std::strerror(err)));
      std::string who(owner, n > 0 ? static_cast<std::size_t>(n) : 0);
      while (!who.empty() && (who.back() == '\n' || who.back() == '\0')) who.pop_back();
      throw OutputDirectoryError(
          fmt::format("output directory {}: another run ({}) is writing into it; wait for it or "
                      "give another --out",
                      dir, who.empty() ? "unknown" : who));
    }
    struct stat held {
    }, now{};
    if (::fstat(fd_, &held) == 0 && ::stat(lock_path_.c_str(), &now) == 0 && held.st_ino == now.st_ino &&
        held.st_dev == now.st_dev)
      break;
    ::close(fd_);
    fd_ = -1;
  }
  if (fd_ < 0) throw OutputDirectoryError(fmt::format("{}: the lock file keeps being replaced", lock_path_));
  const std::string me = fmt::format("pid {}, run {}\n", static_cast<long>(::getpid()), run_id());
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
    // Not fatal: the lock holds without the note of who holds it.
  }
}

OutputDirectoryClaim::~OutputDirectoryClaim() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());  // while still locked: a run that opened the old file sees it replaced
  ::close(fd_);
  std::error_code ec;
  if (created_ && fs::is_empty(directory_, ec)) fs::remove(directory_, ec);
}

}  // namespace pd
