// texrender --watch: what the session reads (Watch.h): the watched files, graph.json's argument
// changes as live edits, and the control channel's bounded lines.
#include "texrender/Watch.h"

#include "WatchSession.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;
using nlohmann::json;

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

std::vector<std::string> graphFiles(const std::string &GraphPath, const json &Graph) {
  std::vector<std::string> Out{GraphPath};
  fs::path Dir = fs::path(GraphPath).parent_path();
  if (Graph.is_object() && Graph.contains("sources") && Graph["sources"].is_array())
    for (const json &S : Graph["sources"])
      if (S.is_string())
        Out.push_back((Dir / S.get<std::string>()).lexically_normal().string());
  return Out;
}

std::optional<std::vector<std::string>> argumentEdits(const json &Old, const json &New) {
  if (!Old.is_object() || !New.is_object())
    return std::nullopt;
  for (auto It = New.begin(); It != New.end(); ++It)
    if (It.key() != "nodes" && (!Old.contains(It.key()) || Old[It.key()] != It.value()))
      return std::nullopt;
  for (auto It = Old.begin(); It != Old.end(); ++It)
    if (!New.contains(It.key()))
      return std::nullopt;
  const json &ON = Old.value("nodes", json::array()), &NN = New.value("nodes", json::array());
  if (!ON.is_array() || !NN.is_array() || ON.size() != NN.size())
    return std::nullopt;
  std::vector<std::string> Edits;
  for (size_t I = 0; I < ON.size(); ++I) {
    const json &A = ON[I], &B = NN[I];
    if (!A.is_object() || !B.is_object() || A.size() != B.size())
      return std::nullopt;
    for (auto It = B.begin(); It != B.end(); ++It)
      if (It.key() != "args" && (!A.contains(It.key()) || A[It.key()] != It.value()))
        return std::nullopt;
    const json &AA = A.value("args", json::object()), &BA = B.value("args", json::object());
    if (!AA.is_object() || !BA.is_object() || AA.size() != BA.size() || !B["id"].is_string())
      return std::nullopt;
    for (auto It = BA.begin(); It != BA.end(); ++It) {
      if (!AA.contains(It.key()))
        return std::nullopt;
      if (AA[It.key()] != It.value())
        Edits.push_back("set " + B["id"].get<std::string>() + "." + It.key() + "=" + It.value().dump());
    }
  }
  return Edits;
}

namespace watch {

void applyToGraphJson(json &G, const Edit &E) {
  if (!G.contains("nodes") || !G["nodes"].is_array())
    return;
  for (json &N : G["nodes"]) {
    if (!N.is_object() || N.value("id", "") != E.Node)
      continue;
    json &Args = N["args"];
    if (E.K == Edit::Kind::Rewire) {
      Args[E.Arg] = json{{"node", E.Value}};
      continue;
    }
    json Value = json::parse(E.Value);
    if (Args.contains(E.Arg) && Args[E.Arg].is_object() && Args[E.Arg].value("bake", false))
      Args[E.Arg]["value"] = Value;
    else
      Args[E.Arg] = Value;
  }
}

} // namespace watch
} // namespace texrender
