#include "texrender/LiveEdit.h"
#include "texrender/Error.h"

#include "texcc/Graph/Edit.h"
#include "texcc/Graph/Graph.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace texrender {

namespace {

std::string trim(const std::string &S) {
  size_t B = S.find_first_not_of(" \t\r\n"), E = S.find_last_not_of(" \t\r\n");
  return B == std::string::npos ? "" : S.substr(B, E - B + 1);
}

std::string readFile(const std::string &Path) {
  std::ifstream In(Path);
  if (!In)
    throw Error(Path + ": cannot open");
  std::stringstream SS;
  SS << In.rdbuf();
  return SS.str();
}

std::string diagnosticsText(const texcc::graph::DiagnosticSink &D) {
  std::ostringstream OS;
  D.print(OS);
  std::string S = OS.str();
  for (char &C : S)
    if (C == '\n')
      C = ' ';
  return trim(S);
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Runs Argv, returning its exit status; its stdout and stderr go to LogPath.
int runProcess(const std::vector<std::string> &Argv, const std::string &LogPath) {
  pid_t Pid = fork();
  if (Pid < 0)
    return -1;
  if (Pid == 0) {
    FILE *Log = std::fopen(LogPath.c_str(), "w");
    if (Log) {
      dup2(fileno(Log), 1);
      dup2(fileno(Log), 2);
    }
    std::vector<char *> Args;
    for (auto &A : Argv)
      Args.push_back(const_cast<char *>(A.c_str()));
    Args.push_back(nullptr);
    execv(Args[0], Args.data());
    _exit(127);
  }
  int Status = 0;
  waitpid(Pid, &Status, 0);
  return WIFEXITED(Status) ? WEXITSTATUS(Status) : -1;
}

} // namespace

std::string findTexcc() {
  if (const char *E = std::getenv("TEXCC"); E && *E)
    return E;
  std::error_code EC;
  fs::path Exe = fs::read_symlink("/proc/self/exe", EC);
  return EC ? "texcc" : (Exe.parent_path() / "texcc").string();
}

Edit parseEdit(const std::string &LineIn) {
  std::string Line = trim(LineIn);
  Edit E;
  E.Text = Line;
  if (Line.rfind("set ", 0) == 0) {
    Line = trim(Line.substr(4));
  } else if (Line.rfind("rewire ", 0) == 0) {
    E.K = Edit::Kind::Rewire;
    Line = trim(Line.substr(7));
  }
  size_t Eq = Line.find('=');
  std::string Lhs = Eq == std::string::npos ? "" : trim(Line.substr(0, Eq));
  size_t Dot = Lhs.rfind('.');
  if (Eq == std::string::npos || Dot == std::string::npos || Dot == 0 || Dot + 1 == Lhs.size())
    throw Error("bad edit '" + E.Text + "': expected NODE.ARG=VALUE (or rewire NODE.ARG=SOURCE)");
  E.Node = Lhs.substr(0, Dot);
  E.Arg = Lhs.substr(Dot + 1);
  E.Value = trim(Line.substr(Eq + 1));
  if (E.Value.empty())
    throw Error("bad edit '" + E.Text + "': missing value after '='");
  return E;
}

LiveEditor::LiveEditor(const Layout &L, std::string Texcc)
    : Lay(L), TexccPath(Texcc.empty() ? findTexcc() : std::move(Texcc)) {
  if (Lay.GraphPath.empty())
    throw Error(Lay.Dir + "/layout.json: no \"graph\": live edits need the graph the kernel was made from");
  std::string Text = readFile(Lay.GraphPath);
  try {
    GraphDoc = json::parse(Text);
  } catch (const json::exception &Ex) {
    throw Error(Lay.GraphPath + ": invalid JSON: " + Ex.what());
  }
  initEditor(Text);
}

void LiveEditor::initEditor(const std::string &GraphText) {
  Editor.reset();
  if (Lay.Mode == "inline")
    return; // every edit regenerates
  texcc::graph::DiagnosticSink Diags;
  std::optional<texcc::graph::Graph> G = texcc::graph::parseGraph(Lay.GraphPath, GraphText, Diags);
  if (!G)
    throw Error(Lay.GraphPath + ": " + diagnosticsText(Diags));
  texcc::graph::SignatureMap Sigs;
  texcc::graph::CompileOptions Opts;
  std::string Why;
  if (!texcc::graph::readLayoutSignatures(Lay.Text, Sigs, Opts.FixedFunctionIds, Why))
    throw Error(Lay.Dir + "/layout.json: " + Why);
  Opts.StackLimit = Lay.StackLimit;
  Editor = std::make_unique<texcc::graph::GraphEditor>(std::move(*G), std::move(Sigs), Opts);
  if (!Editor->init(Diags))
    throw Error(Lay.GraphPath + ": " + diagnosticsText(Diags));
}

LiveEditor::~LiveEditor() = default;

void LiveEditor::applyToJson(const Edit &E) {
  if (!GraphDoc.contains("nodes") || !GraphDoc["nodes"].is_array())
    throw Error("edit '" + E.Text + "': " + Lay.GraphPath + " has no nodes");
  for (json &N : GraphDoc["nodes"]) {
    if (N.value("id", "") != E.Node)
      continue;
    if (E.K == Edit::Kind::Rewire) {
      N["args"][E.Arg] = json{{"node", E.Value}};
      return;
    }
    try {
      N["args"][E.Arg] = json::parse(E.Value);
    } catch (const json::exception &) {
      throw Error("edit '" + E.Text + "': value '" + E.Value + "' is not a number or array");
    }
    return;
  }
  throw Error("edit '" + E.Text + "': unknown node '" + E.Node + "'");
}

void LiveEditor::regenerate(Renderer &R) {
  // The edited graph, with its sources and images made absolute, in a fresh folder.
  fs::path GraphDir = fs::path(Lay.GraphPath).parent_path();
  json Doc = GraphDoc;
  if (Doc.contains("sources"))
    for (json &S : Doc["sources"])
      S = (GraphDir / S.get<std::string>()).lexically_normal().string();
  if (Doc.contains("images"))
    for (auto &[K, V] : Doc["images"].items()) {
      (void)K;
      V = (GraphDir / V.get<std::string>()).lexically_normal().string();
    }
  fs::path Work = fs::temp_directory_path() /
                  ("texrender-edit-" + std::to_string(getpid()) + "-" + std::to_string(++Generation));
  fs::create_directories(Work);
  fs::path Graph = Work / fs::path(Lay.GraphPath).filename();
  std::ofstream(Graph) << Doc.dump(2);
  fs::path Out = Work / "out";
  if (!fs::exists(TexccPath))
    throw Error("this edit needs the texture kernel regenerated, but texcc was not found at " +
                TexccPath + " (set TEXCC, or re-run texcc and restart texrender)");
  std::string Log = (Work / "texcc.log").string();
  int Rc = runProcess({TexccPath, "--graph", Graph.string(), "--mode=" + Lay.Mode, "-o", Out.string()}, Log);
  if (Rc != 0) {
    std::string Msg = trim(readFile(Log));
    throw Error("regenerating the texture kernel failed (texcc exit " + std::to_string(Rc) + "): " +
                Msg.substr(0, Msg.find('\n')));
  }
  Layout New = loadLayout(Out.string());
  R.setLayout(New);
  // Later edits address the regenerated kernel; the graph keeps its original folder for
  // resolving relative paths.
  std::string Original = Lay.GraphPath;
  Lay = New;
  Lay.GraphPath = Graph.string();
  initEditor(Doc.dump());
  Lay.GraphPath = Original;
}

EditResult LiveEditor::apply(const Edit &E, Renderer &R) {
  double T0 = now();
  EditResult Res;
  applyToJson(E);
  bool Regenerate = Lay.Mode == "inline";
  if (!Regenerate) {
    texcc::graph::DiagnosticSink Diags;
    bool Ok = E.K == Edit::Kind::Set ? Editor->setArgument(E.Node, E.Arg, E.Value, Diags)
                                     : Editor->rewire(E.Node, E.Arg, E.Value, Diags);
    if (!Ok)
      throw Error("edit '" + E.Text + "': " + diagnosticsText(Diags));
    // A rewiring changes the launch plan (wavefront) or the graph shape (shape mode).
    Regenerate = Editor->needsRebuild() || (E.K == Edit::Kind::Rewire && Lay.Mode != "interp");
    if (!Regenerate) {
      const auto &CG = Editor->compiled();
      R.applyArguments(CG.ArgsBin, CG.Attributes);
    }
  }
  if (Regenerate) {
    regenerate(R);
    Res.Rebuilt = true;
  }
  R.cl().finish();
  Res.Seconds = now() - T0;
  return Res;
}

} // namespace texrender
