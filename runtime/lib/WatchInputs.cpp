// texrender --watch: what the session reads (Watch.h): the watched files and the control
// channel's bounded lines.
#include "texrender/Watch.h"

#include "WatchSession.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace texrender {

LineRead readBoundedLine(std::istream &In, std::string &Line, size_t Max) {
  Line.clear();
  std::streambuf *Buf = In.rdbuf();
  for (bool Any = false;; Any = true) {
    int C = Buf->sbumpc();
    if (C == std::char_traits<char>::eof())
      return Any ? LineRead::Line : LineRead::End;
    if (C == '\n')
      return LineRead::Line;
    if (Line.size() == Max)
      return LineRead::TooLong;
    Line.push_back(char(C));
  }
}

FileWatcher::Seen FileWatcher::look(const std::string &Path) {
  Seen S;
  S.Path = Path;
  struct stat St;
  if (::stat(Path.c_str(), &St) == 0) {
    S.Exists = true;
    S.Size = St.st_size;
    S.MTimeNs = (long long)St.st_mtim.tv_sec * 1000000000LL + St.st_mtim.tv_nsec;
  }
  return S;
}

void FileWatcher::watch(const std::vector<std::string> &Paths) {
  std::vector<Seen> Next;
  for (const std::string &P : Paths) {
    auto Old = std::find_if(Files.begin(), Files.end(), [&](const Seen &S) { return S.Path == P; });
    Next.push_back(Old != Files.end() ? *Old : look(P));
  }
  Files = std::move(Next);
}

std::vector<std::string> FileWatcher::changed() {
  std::vector<std::string> Out;
  for (Seen &S : Files) {
    Seen Now = look(S.Path);
    if (Now.Exists != S.Exists || Now.Size != S.Size || Now.MTimeNs != S.MTimeNs)
      Out.push_back(S.Path);
    S = Now;
  }
  return Out;
}

std::vector<std::string> graphFiles(const std::string &GraphPath,
                                    const std::vector<std::string> &Sources) {
  std::vector<std::string> Out{GraphPath};
  fs::path Dir = fs::path(GraphPath).parent_path();
  for (const std::string &S : Sources)
    Out.push_back((Dir / S).lexically_normal().string());
  return Out;
}

} // namespace texrender
