// Atomic output: every file goes to a temporary name in OUTDIR first; only when all are written
// are they renamed into place, so an error leaves the previous outputs as they were.
#include "texcc/Codegen/Codegen.h"
#include "texcc/StaleTemporaries.h"
#include "texcc/Support/AtomicWrite.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texcc::codegen {

static void removeAll(const std::vector<fs::path> &Paths) {
  std::error_code Ignored;
  for (const fs::path &P : Paths)
    fs::remove(P, Ignored);
}

bool writeOutputsAtomically(const std::string &Dir, const std::vector<OutputFile> &Files,
                            std::string &Error) {
  std::error_code EC;
  fs::create_directories(Dir, EC);
  if (EC) {
    Error = "cannot create output folder '" + Dir + "': " + EC.message();
    return false;
  }
  for (const OutputFile &F : Files) {
    std::string Why;
    if (!texcc::checkReplaceable((fs::path(Dir) / F.Name).string(), Why)) {
      Error = "cannot write '" + (fs::path(Dir) / F.Name).string() + "': " + Why;
      return false;
    }
  }
  std::vector<std::string> Names;
  for (const OutputFile &F : Files)
    Names.push_back(F.Name);
  texcc::removeStaleTemporaries(Dir, Names);
  const std::string Suffix = ".tmp" + std::to_string(static_cast<long>(::getpid()));
  std::vector<fs::path> Temps;
  for (const OutputFile &F : Files) {
    fs::path Temp = fs::path(Dir) / ("." + F.Name + Suffix);
    Temps.push_back(Temp);
    std::string Why;
    if (!texcc::writeWholeFile(Temp.string(), F.Contents.data(), F.Contents.size(), Why)) {
      // Named by the output it was for: the temporary is gone.
      Error = "cannot write '" + (fs::path(Dir) / F.Name).string() + "': " + Why;
      removeAll(Temps);
      return false;
    }
  }
  // Put the new files in place one by one, keeping a hard link to each old one until all are
  // in, so that a failure half way can restore the previous outputs exactly. The old file
  // stays under its name until rename() replaces it in one step: a process killed at any
  // point leaves every output name with its old or its new complete contents, never missing.
  std::vector<std::pair<fs::path, fs::path>> Saved; // target, backup
  std::vector<fs::path> Placed;
  for (size_t I = 0; I < Files.size() && !EC; ++I) {
    fs::path Target = fs::path(Dir) / Files[I].Name;
    if (fs::exists(fs::symlink_status(Target))) {
      fs::path Backup = fs::path(Dir) / ("." + Files[I].Name + ".old" + Suffix);
      fs::create_hard_link(Target, Backup, EC);
      if (EC) { // a file system without hard links: a copy does as well, more slowly
        EC.clear();
        fs::copy_file(Target, Backup, fs::copy_options::overwrite_existing, EC);
      }
      if (EC)
        break;
      Saved.push_back({Target, Backup});
    }
    fs::rename(Temps[I], Target, EC);
    if (!EC)
      Placed.push_back(Target);
  }
  if (EC) {
    Error = "cannot write the outputs into '" + Dir + "': " + EC.message();
    removeAll(Placed);
    std::error_code Ignored;
    for (const auto &[Target, Backup] : Saved)
      fs::rename(Backup, Target, Ignored);
    removeAll(Temps);
    return false;
  }
  std::vector<fs::path> Backups;
  for (const auto &Entry : Saved)
    Backups.push_back(Entry.second);
  removeAll(Backups);
  return true;
}

} // namespace texcc::codegen
