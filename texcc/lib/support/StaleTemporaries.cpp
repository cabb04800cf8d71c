// Stale output temporaries (see StaleTemporaries.h). In the support library, which texcc and
// texrender both link.
#include "texcc/StaleTemporaries.h"

#include <cerrno>
#include <csignal>
#include <filesystem>

namespace fs = std::filesystem;

namespace texcc {

void removeStaleTemporaries(const std::string &Dir, const std::vector<std::string> &Names) {
  std::error_code EC;
  for (const fs::directory_entry &E : fs::directory_iterator(Dir.empty() ? "." : Dir, EC)) {
    const std::string Name = E.path().filename().string();
    for (const std::string &N : Names)
      for (const std::string &Prefix : {"." + N + ".tmp", "." + N + ".old.tmp"}) {
        if (Name.compare(0, Prefix.size(), Prefix) != 0)
          continue;
        // "<pid>", or "<pid>.<n>" (writeAtomicallyWith's further writes of one process).
        const std::string Rest = Name.substr(Prefix.size());
        const std::string Pid = Rest.substr(0, Rest.find('.'));
        const std::string Count = Rest.size() > Pid.size() ? Rest.substr(Pid.size() + 1) : "0";
        if (Count.empty() || Count.find_first_not_of("0123456789") != std::string::npos)
          continue;
        if (Pid.empty() || Pid.size() > 9 || Pid.find_first_not_of("0123456789") != std::string::npos)
          continue;
        if (::kill(static_cast<pid_t>(std::stol(Pid)), 0) != 0 && errno == ESRCH) {
          std::error_code Ignored;
          fs::remove(E.path(), Ignored);
        }
      }
  }
}

} // namespace texcc
