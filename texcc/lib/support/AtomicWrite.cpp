#include "texcc/Support/AtomicWrite.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texcc {

bool writeWholeFile(const std::string &Path, const void *Data, size_t Size, std::string &Why) {
  int Fd;
  do
    Fd = ::open(Path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  while (Fd < 0 && errno == EINTR);
  if (Fd < 0) {
    Why = std::strerror(errno);
    return false;
  }
  const char *P = static_cast<const char *>(Data);
  size_t Left = Size;
  while (Left > 0) {
    // At most 1 GiB a call (Linux writes at most 2 GiB - 4 KiB at once anyway).
    ssize_t N = ::write(Fd, P, std::min(Left, size_t(1) << 30));
    if (N < 0 && errno == EINTR)
      continue;
    if (N <= 0) {
      Why = N < 0 ? std::strerror(errno) : "write wrote nothing";
      ::close(Fd);
      return false;
    }
    P += N;
    Left -= size_t(N);
  }
  // close() reports a delayed write error (NFS, some FUSE file systems); it is not retried on
  // EINTR (the descriptor is gone either way), which is then the error.
  if (::close(Fd) != 0) {
    Why = std::strerror(errno);
    return false;
  }
  return true;
}

bool checkReplaceable(const std::string &Path, std::string &Why) {
  struct stat St;
  if (::stat(Path.c_str(), &St) != 0)
    return true; // none (or a dangling symlink): the rename makes it
  if (S_ISREG(St.st_mode))
    return true;
  if (S_ISDIR(St.st_mode))
    Why = "it is a folder";
  else if (S_ISFIFO(St.st_mode))
    Why = "it is a FIFO, not a regular file";
  else if (S_ISCHR(St.st_mode) || S_ISBLK(St.st_mode))
    Why = "it is a device, not a regular file";
  else if (S_ISSOCK(St.st_mode))
    Why = "it is a socket, not a regular file";
  else
    Why = "it is not a regular file";
  return false;
}

/// ".NAME.tmp<pid>" for a process's first write, ".NAME.tmp<pid>.<n>" after: unique per write,
/// so threads writing the same file (background kernel builds storing one cache entry) never
/// share a temporary.
static fs::path temporaryFor(const fs::path &Target) {
  static std::atomic<unsigned> Count{0};
  const unsigned N = Count++;
  std::string Name = "." + Target.filename().string() + ".tmp" + std::to_string(::getpid());
  if (N)
    Name += "." + std::to_string(N);
  return Target.parent_path() / Name;
}

std::string temporaryPathFor(const std::string &Path) { return temporaryFor(Path).string(); }

bool writeAtomicallyWith(const std::string &Path,
                         const std::function<bool(const std::string &, std::string &)> &Write,
                         std::string &Why) {
  if (!checkReplaceable(Path, Why))
    return false;
  const fs::path Target(Path);
  const fs::path Temp = temporaryFor(Target);
  std::error_code Ignored;
  bool Written = false;
  try {
    Written = Write(Temp.string(), Why);
  } catch (...) {
    fs::remove(Temp, Ignored);
    throw;
  }
  if (!Written) {
    fs::remove(Temp, Ignored);
    return false;
  }
  std::error_code EC;
  fs::rename(Temp, Target, EC);
  if (EC) {
    fs::remove(Temp, Ignored);
    Why = EC.message();
    return false;
  }
  return true;
}

bool writeFileAtomically(const std::string &Path, const void *Data, size_t Size, std::string &Why) {
  return writeAtomicallyWith(
      Path, [&](const std::string &Temp, std::string &W) { return writeWholeFile(Temp, Data, Size, W); },
      Why);
}

bool writeFileAtomically(const std::string &Path, const std::string &Contents, std::string &Why) {
  return writeFileAtomically(Path, Contents.data(), Contents.size(), Why);
}

} // namespace texcc
