#include "texcc/Support/AtomicWrite.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texcc {

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

bool writeAtomicallyWith(const std::string &Path,
                         const std::function<bool(const std::string &, std::string &)> &Write,
                         std::string &Why) {
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

bool writeFileAtomically(const std::string &Path, const std::string &Contents, std::string &Why) {
  return writeAtomicallyWith(
      Path,
      [&](const std::string &Temp, std::string &W) {
        errno = 0;
        std::ofstream Out(Temp, std::ios::binary | std::ios::trunc);
        Out.write(Contents.data(), static_cast<std::streamsize>(Contents.size()));
        Out.close();
        if (Out)
          return true;
        W = errno ? std::strerror(errno) : "write failed";
        return false;
      },
      Why);
}

} // namespace texcc
