#ifndef TEXCC_FUZZ_FUZZFILE_H
#define TEXCC_FUZZ_FUZZFILE_H

// A file that a fuzz input is written to, for the loaders that only take a path (scene.json,
// OBJ). It lives in a folder of its own per process (mkdtemp), so that fuzzers running as
// parallel jobs do not overwrite each other's input, and is removed at exit.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace texcc::fuzz {

class ScratchFile {
public:
  explicit ScratchFile(const std::string &Name) {
    std::string Template =
        (std::filesystem::temp_directory_path() / "texcc-fuzz-XXXXXX").string();
    if (!mkdtemp(Template.data())) {
      std::perror("texcc-fuzz: mkdtemp");
      std::abort();
    }
    Dir = Template;
    Path = Dir + "/" + Name;
  }
  ~ScratchFile() {
    std::error_code EC;
    std::filesystem::remove_all(Dir, EC);
  }
  ScratchFile(const ScratchFile &) = delete;
  ScratchFile &operator=(const ScratchFile &) = delete;

  void write(const uint8_t *Data, size_t Size) const {
    FILE *F = std::fopen(Path.c_str(), "wb");
    if (!F || std::fwrite(Data, 1, Size, F) != Size || std::fclose(F) != 0) {
      std::perror("texcc-fuzz: writing the input file");
      std::abort();
    }
  }
  const std::string &path() const { return Path; }

private:
  std::string Dir, Path;
};

} // namespace texcc::fuzz

#endif
