// Atomic output: every file goes to a temporary name in OUTDIR first; only when all are written
// are they renamed into place, so an error leaves the previous outputs as they were.
#include "texcc/Codegen/Codegen.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
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
  const std::string Suffix = ".tmp" + std::to_string(static_cast<long>(::getpid()));
  std::vector<fs::path> Temps;
  for (const OutputFile &F : Files) {
    fs::path Temp = fs::path(Dir) / ("." + F.Name + Suffix);
    Temps.push_back(Temp);
    std::ofstream OS(Temp, std::ios::binary | std::ios::trunc);
    OS.write(F.Contents.data(), static_cast<std::streamsize>(F.Contents.size()));
    OS.close();
    if (!OS) {
      Error = "cannot write '" + Temp.string() + "': " + std::strerror(errno);
      removeAll(Temps);
      return false;
    }
  }
  for (size_t I = 0; I < Files.size(); ++I) {
    fs::rename(Temps[I], fs::path(Dir) / Files[I].Name, EC);
    if (EC) {
      Error = "cannot rename '" + Temps[I].string() + "': " + EC.message();
      removeAll(Temps);
      return false;
    }
  }
  return true;
}

} // namespace texcc::codegen
