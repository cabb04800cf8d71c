#include "texrender/LiveEdit.h"
#include "texrender/EditPlan.h"
#include "texrender/Error.h"
#include "texrender/Image.h"

#include "texcc/Graph/Edit.h"
#include "texcc/Graph/Graph.h"
#include "texcc/Kernel/Manifest.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/AtomicWrite.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace texrender {

namespace {

std::string trim(const std::string &S) {
  size_t B = S.find_first_not_of(" \t\r\n"), E = S.find_last_not_of(" \t\r\n");
  return B == std::string::npos ? "" : S.substr(B, E - B + 1);
}

std::string readFile(const std::string &Path) { return readWholeFile(Path); }

std::string diagnosticsText(const texcc::graph::DiagnosticSink &D) {
  std::ostringstream OS;
  D.print(OS);
  std::string S = OS.str();
  for (char &C : S)
    if (C == '\n')
      C = ' ';
  return trim(S);
}

/// The message of D's first error (its location is the edit's, not the graph's).
std::string firstError(const texcc::graph::DiagnosticSink &D) {
  for (const texcc::graph::Diagnostic &E : D.diagnostics())
    if (E.Level == texcc::graph::Diagnostic::Severity::Error)
      return E.Message;
  return diagnosticsText(D);
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Runs Argv, returning its exit status; its stdout and stderr go to LogPath. posix_spawn,
/// not fork: the renderer's background thread runs texcc, and a forked child of a threaded
/// process may only call async-signal-safe functions.
int runProcess(const std::vector<std::string> &Argv, const std::string &LogPath) {
  std::vector<char *> Args;
  for (auto &A : Argv)
    Args.push_back(const_cast<char *>(A.c_str()));
  Args.push_back(nullptr);
  posix_spawn_file_actions_t Actions;
  posix_spawn_file_actions_init(&Actions);
  posix_spawn_file_actions_addopen(&Actions, 1, LogPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&Actions, 1, 2);
  pid_t Pid = 0;
  int Rc = posix_spawn(&Pid, Args[0], &Actions, nullptr, Args.data(), environ);
  posix_spawn_file_actions_destroy(&Actions);
  if (Rc != 0)
    return -1;
  int Status = 0;
  waitpid(Pid, &Status, 0);
  return WIFEXITED(Status) ? WEXITSTATUS(Status) : -1;
}

/// Arguments baked on texcc's command line (--bake NODE.ARG) are marked "bake" in layout.json's
/// nodes (the kernel manifest) but absent from graph.json: marks them baked in G, so that a
/// regeneration keeps them baked and an edit of one is known to change the shape. M is the
/// layout's manifest as loadLayout read it (layout.json is parsed once).
void carryCommandLineBakes(texcc::graph::Graph &G, const texcc::kernel::Manifest &M) {
  std::map<std::string, std::vector<std::string>> Baked; // node id -> baked argument names
  for (const texcc::kernel::NodeLayout &N : M.Nodes)
    for (const texcc::kernel::ArgLayout &A : N.Args) {
      if (!A.Bake)
        continue;
      Baked[N.Id].push_back(A.Name);
      for (const std::string &Merged : N.Merged)
        Baked[Merged].push_back(A.Name);
    }
  using Kind = texcc::graph::ArgValue::Kind;
  for (texcc::graph::Node &N : G.Nodes) {
    auto It = Baked.find(N.Id);
    if (It == Baked.end())
      continue;
    for (auto &[Name, A] : N.Args)
      if (std::find(It->second.begin(), It->second.end(), Name) != It->second.end() &&
          A.K != Kind::NodeRef && A.K != Kind::AttrRef && A.K != Kind::ImageRef)
        A.Bake = true;
  }
}

json argumentJson(const texcc::graph::ArgValue &A) {
  using Kind = texcc::graph::ArgValue::Kind;
  auto Number = [&](double D) { return A.IsInteger ? json(int64_t(D)) : json(D); };
  auto Numbers = [&](const std::vector<double> &Ds) {
    json Arr = json::array();
    for (double D : Ds)
      Arr.push_back(Number(D));
    return Arr;
  };
  json V;
  switch (A.K) {
  case Kind::NodeRef:
    return json{{"node", A.Ref}};
  case Kind::AttrRef:
    return json{{"attr", A.Ref}};
  case Kind::ImageRef:
    return json{{"image", A.Ref}};
  case Kind::Number:
    V = Number(A.Numbers.empty() ? 0.0 : A.Numbers[0]);
    break;
  case Kind::Vector:
  case Kind::Array:
    if (A.IsArrayOfRows) {
      V = json::array();
      for (const std::vector<double> &Row : A.Rows)
        V.push_back(Numbers(Row));
    } else {
      V = Numbers(A.Numbers);
    }
    break;
  }
  if (A.Bake)
    return json{{"value", V}, {"bake", true}};
  return V;
}

json bsdfJson(const texcc::graph::Bsdf &B) {
  json J;
  J["bsdf"] = B.Type;
  for (const auto &[Name, V] : B.Inputs)
    J[Name] = argumentJson(V);
  for (const auto &[Name, Child] : B.Children)
    J[Name] = bsdfJson(Child);
  return J;
}

} // namespace

json graphJson(const texcc::graph::Graph &G) {
  json J;
  J["texcc"] = 1;
  J["sources"] = G.Sources;
  if (!G.Images.empty()) {
    json Images = json::object();
    for (const auto &[Name, Path] : G.Images) {
      auto Cs = G.ImageColorSpaces.find(Name);
      if (Cs == G.ImageColorSpaces.end())
        Images[Name] = Path;
      else
        Images[Name] = json{{"path", Path}, {"colorspace", Cs->second}};
    }
    J["images"] = Images;
  }
  json Nodes = json::array();
  for (const texcc::graph::Node &N : G.Nodes) {
    json Args = json::object();
    for (const auto &[Name, V] : N.Args)
      Args[Name] = argumentJson(V);
    Nodes.push_back(json{{"id", N.Id}, {"fn", N.Fn}, {"args", Args}});
  }
  J["nodes"] = Nodes;
  json Materials = json::object();
  for (const texcc::graph::Material &M : G.Materials)
    Materials[M.Name] = bsdfJson(M.Root);
  J["materials"] = Materials;
  return J;
}

std::string findTexcc() {
  if (const char *E = std::getenv("TEXCC"); E && *E)
    return E;
  std::error_code EC;
  fs::path Exe = fs::read_symlink("/proc/self/exe", EC);
  return EC ? "texcc" : (Exe.parent_path() / "texcc").string();
}

Edit parseEdit(const std::string &LineIn) {
  // Positions are kept in LineIn, so that a diagnostic can point at a column.
  auto skipBlanks = [&](size_t P) {
    while (P < LineIn.size() && (LineIn[P] == ' ' || LineIn[P] == '\t'))
      ++P;
    return P;
  };
  std::string Line = trim(LineIn);
  Edit E;
  E.Text = Line;
  size_t Start = skipBlanks(0);
  E.NodeCol = E.ArgCol = E.ValueCol = unsigned(Start + 1);
  if (Line == "wait") {
    E.K = Edit::Kind::Wait;
    return E;
  }
  size_t Pos = Start;
  if (LineIn.compare(Start, 4, "set ") == 0) {
    Pos = skipBlanks(Start + 4);
  } else if (LineIn.compare(Start, 7, "rewire ") == 0) {
    E.K = Edit::Kind::Rewire;
    Pos = skipBlanks(Start + 7);
  }
  size_t Eq = LineIn.find('=', Pos);
  std::string Lhs = Eq == std::string::npos ? "" : trim(LineIn.substr(Pos, Eq - Pos));
  size_t Dot = Lhs.rfind('.');
  E.NodeCol = unsigned(Pos + 1);
  if (Eq == std::string::npos || Dot == std::string::npos || Dot == 0 || Dot + 1 == Lhs.size())
    throw Error("bad edit '" + E.Text + "': expected NODE.ARG=VALUE (or rewire NODE.ARG=SOURCE)");
  E.Node = Lhs.substr(0, Dot);
  E.Arg = Lhs.substr(Dot + 1);
  E.ArgCol = unsigned(Pos + Dot + 2);
  size_t ValuePos = skipBlanks(Eq + 1);
  E.ValueCol = unsigned(ValuePos + 1);
  E.Value = trim(LineIn.substr(Eq + 1));
  if (E.Value.empty())
    throw Error("bad edit '" + E.Text + "': missing value after '='");
  return E;
}

LiveEditor::LiveEditor(const Layout &L, std::shared_ptr<const Regenerator> R)
    : Lay(L), Regen(R ? std::move(R) : std::make_shared<const Regenerator>()) {
  if (Lay.GraphPath.empty())
    throw Error(Lay.Dir + "/layout.json: no \"graph\": live edits need the graph the kernel was made from");
  texcc::graph::DiagnosticSink Diags;
  std::optional<texcc::graph::Graph> G =
      texcc::graph::parseGraph(Lay.GraphPath, readGraphFile(Lay.GraphPath), Diags);
  if (!G)
    throw Error(Lay.GraphPath + ": " + diagnosticsText(Diags));
  Model = std::move(*G);
  carryCommandLineBakes(Model, Lay.Manifest);
  initEditor(Model);
}

void LiveEditor::initEditor(const texcc::graph::Graph &G) {
  Editor.reset();
  KernelShapeHash = Lay.ShapeHash;
  if (!Lay.Caps.ReEncodes)
    return; // every edit regenerates
  Editor = makeEditor(G);
}

std::unique_ptr<texcc::graph::GraphEditor>
LiveEditor::makeEditor(texcc::graph::Graph G) const {
  texcc::graph::DiagnosticSink Diags;
  texcc::graph::SignatureMap Sigs;
  texcc::graph::CompileOptions Opts;
  std::string Why;
  // The kernel's quickened opcodes: an edit re-encodes one only where its pattern still
  // occurs, the plain opcodes elsewhere (docs/modes.md).
  if (!texcc::graph::readLayoutSignatures(Lay.Manifest, Sigs, Opts.FixedFunctionIds, Why) ||
      !texcc::graph::readLayoutQuickened(Lay.Manifest, Opts.Quickened, Why))
    throw Error(Lay.Dir + "/layout.json: " + Why);
  // layout.json lists the function of every node, dead ones included, and the interp kernel
  // (interp mode, shape mode's fallback) has a case for each: a rewiring onto any node is a
  // re-encoding with the ids pinned, never a new function.
  Opts.StackLimit = Lay.StackLimit;
  // An interp kernel that hoists reads every hoisting node's values from its record: a
  // rewiring of a parameter they come from needs a new kernel (texcc then hoists less).
  Opts.InterpHoistedCalls = Lay.Caps.WiringIsData && !Lay.Uniforms.empty();
  auto E = std::make_unique<texcc::graph::GraphEditor>(std::move(G), std::move(Sigs), Opts);
  if (!E->init(Diags))
    throw Error(Lay.GraphPath + ": " + diagnosticsText(Diags));
  return E;
}

std::optional<EditProblem> LiveEditor::check(const std::vector<Edit> &Edits) const {
  std::unique_ptr<texcc::graph::GraphEditor> Scratch = makeEditor(Model);
  for (size_t I = 0; I < Edits.size(); ++I) {
    const Edit &E = Edits[I];
    if (E.K == Edit::Kind::Wait)
      continue;
    texcc::graph::DiagnosticSink Diags;
    bool Ok = E.K == Edit::Kind::Set ? Scratch->setArgument(E.Node, E.Arg, E.Value, Diags)
                                     : Scratch->rewire(E.Node, E.Arg, E.Value, Diags);
    if (Ok)
      continue;
    // Point at the part at fault: the node, else the parameter, else the value.
    const texcc::graph::Node *N = Scratch->graph().findNode(E.Node);
    unsigned Col = E.ValueCol;
    if (!N) {
      Col = E.NodeCol;
    } else {
      const auto &Sigs = Scratch->compiled().Signatures;
      auto Sig = Sigs.find(N->Fn);
      if (Sig != Sigs.end() &&
          std::none_of(Sig->second.Params.begin(), Sig->second.Params.end(),
                       [&](const texcc::graph::Param &P) { return P.Name == E.Arg; }))
        Col = E.ArgCol;
    }
    return EditProblem{I, Col, firstError(Diags)};
  }
  return std::nullopt;
}

LiveEditor::~LiveEditor() = default;

bool LiveEditor::applyToModel(const Edit &E) {
  using Kind = texcc::graph::ArgValue::Kind;
  texcc::graph::Node *N = Model.findNode(E.Node);
  if (!N)
    throw Error("edit '" + E.Text + "': unknown node '" + E.Node + "'");
  auto Slot = std::find_if(N->Args.begin(), N->Args.end(),
                           [&](const auto &A) { return A.first == E.Arg; });
  const bool Had = Slot != N->Args.end();
  const bool WasWired =
      Had && (Slot->second.Bake || Slot->second.K == Kind::NodeRef ||
              Slot->second.K == Kind::AttrRef || Slot->second.K == Kind::ImageRef);
  texcc::graph::ArgValue New;
  if (E.K == Edit::Kind::Rewire) {
    New.K = Kind::NodeRef;
    New.Ref = E.Value;
  } else {
    texcc::graph::DiagnosticSink Diags;
    std::optional<texcc::graph::ArgValue> V =
        texcc::graph::parseArgValue(E.Node + "." + E.Arg, E.Value, Diags);
    if (!V) {
      if (!json::accept(E.Value))
        throw Error("edit '" + E.Text + "': value '" + E.Value + "' is not a number or array");
      throw Error("edit '" + E.Text + "': " + firstError(Diags));
    }
    New = std::move(*V);
    // A baked constant ({"value": v, "bake": true}) is a literal of the shape code: it stays
    // baked, and changing it changes the shape.
    New.Bake |= Had && Slot->second.Bake;
  }
  if (Had) {
    New.KeyLoc = Slot->second.KeyLoc;
    Slot->second = std::move(New);
  } else {
    N->Args.emplace_back(E.Arg, std::move(New));
  }
  // A set to {"attr": ...} or {"node": ...} is a wiring too.
  const texcc::graph::ArgValue &Now = Had ? Slot->second : N->Args.back().second;
  return E.K == Edit::Kind::Rewire || WasWired || Now.K == Kind::NodeRef ||
         Now.K == Kind::AttrRef;
}

texcc::graph::Graph LiveEditor::absoluteGraph() const {
  fs::path GraphDir = fs::path(Lay.GraphPath).parent_path();
  texcc::graph::Graph G = Model;
  for (std::string &S : G.Sources)
    S = (GraphDir / S).lexically_normal().string();
  for (auto &[Name, Path] : G.Images) {
    (void)Name;
    Path = (GraphDir / Path).lexically_normal().string();
  }
  return G;
}

TempFolder::TempFolder(std::string P) : Path(std::move(P)) { fs::create_directories(Path); }

TempFolder::~TempFolder() {
  std::error_code EC; // nothing to do about a folder that cannot be removed
  fs::remove_all(Path, EC);
}

Regeneration::Regeneration(std::shared_ptr<const TempFolder> F, std::string G, std::string T,
                           std::vector<std::string> Opts)
    : Folder(std::move(F)), Graph(std::move(G)), Texcc(std::move(T)),
      Out(Folder->path() + "/out"), Log(Folder->path() + "/texcc.log"), Options(std::move(Opts)) {}

Regeneration::~Regeneration() {
  if (Thread.joinable())
    Thread.join();
}

Layout Regeneration::run() const {
  std::vector<std::string> Argv{Texcc, "--graph", Graph, "-o", Out};
  Argv.insert(Argv.end(), Options.begin(), Options.end());
  int Rc = runProcess(Argv, Log);
  if (Rc != 0) {
    std::string Msg = trim(readFile(Log));
    throw Error("regenerating the texture kernel failed (texcc exit " + std::to_string(Rc) + "): " +
                Msg.substr(0, Msg.find('\n')));
  }
  return loadLayout(Out);
}

void Regeneration::start(std::function<void()> Notify) {
  Thread = std::thread([this, Notify = std::move(Notify)] {
    try {
      Result = run();
    } catch (const std::exception &E) {
      std::error_code EC;
      Failure = fs::exists(Log, EC) ? readWholeFile(Log) : std::string(E.what());
    }
    EndedAt = now();
    Done.store(true);
    if (Notify)
      Notify();
  });
}

std::optional<Layout> Regeneration::takeResult() {
  if (Thread.joinable())
    Thread.join();
  return std::move(Result);
}

Regenerator::Regenerator(std::string T) : Texcc(T.empty() ? findTexcc() : std::move(T)) {}

std::shared_ptr<const TempFolder> Regenerator::newFolder() const {
  static std::atomic<unsigned> Count{0}; // one numbering per process
  return std::make_shared<const TempFolder>(
      (fs::temp_directory_path() /
       ("texrender-edit-" + std::to_string(getpid()) + "-" + std::to_string(++Count)))
          .string());
}

std::shared_ptr<Regeneration> Regenerator::ofFile(const std::string &Path,
                                                  const std::vector<std::string> &Options) const {
  return std::make_shared<Regeneration>(newFolder(), Path, Texcc, Options);
}

std::shared_ptr<Regeneration> Regenerator::ofGraph(const texcc::graph::Graph &G,
                                                   const std::string &FileName,
                                                   const std::vector<std::string> &Options) const {
  std::shared_ptr<const TempFolder> Folder = newFolder();
  const std::string Path = Folder->path() + "/" + FileName;
  std::string Why;
  if (!texcc::writeFileAtomically(Path, graphJson(G).dump(2), Why))
    throw Error("cannot write the edited graph for texcc to '" + Path + "': " + Why);
  return std::make_shared<Regeneration>(std::move(Folder), Path, Texcc, Options);
}

std::shared_ptr<Regeneration> LiveEditor::writeEditedGraph() {
  if (!fs::exists(Regen->texcc()))
    throw Error("this edit needs the texture kernel regenerated, but texcc was not found at " +
                Regen->texcc() + " (set TEXCC, or re-run texcc and restart texrender)");
  return Regen->ofGraph(absoluteGraph(), fs::path(Lay.GraphPath).filename().string(),
                        Lay.CompileOptions);
}

void LiveEditor::adopt(const Layout &New, const Regeneration &Files) {
  // Later edits address the regenerated kernel; the graph keeps its original folder for
  // resolving relative paths. The editor compiles the graph as it is now (edits made while a
  // background build ran included).
  std::string Original = Lay.GraphPath;
  texcc::graph::Graph Absolute = absoluteGraph();
  Lay = New;
  Lay.GraphPath = Absolute.Path = Files.graph();
  initEditor(Absolute);
  Lay.GraphPath = Original;
  PreviousFolder = std::move(KernelFolder);
  KernelFolder = Files.folder();
}

void LiveEditor::regenerate(Renderer &R) {
  std::shared_ptr<Regeneration> Files = writeEditedGraph();
  Layout New = Files->run();
  R.setLayout(New);
  adopt(New, *Files);
}

void LiveEditor::regenerateInBackground(Renderer &R) {
  std::shared_ptr<const Regeneration> Files = writeEditedGraph();
  const auto &CG = Editor->compiled();
  KernelShapeHash = texcc::graph::shapeHash(CG);
  R.switchShapes(
      CG.ArgsBin, CG.Attributes, [Files] { return Files->run(); },
      [this, Files](Layout &New) {
        adopt(New, *Files);
        New.ArgsBin = Editor->compiled().ArgsBin;
        New.Attributes = Editor->compiled().Attributes;
      });
}

EditAction LiveEditor::plan(const Edit &E, bool Structural, Renderer &R) {
  if (!Lay.Caps.ReEncodes)
    return planEdit({}, Lay.Caps, {});
  texcc::graph::DiagnosticSink Diags;
  bool Ok = texcc::whileAllocating("encoding the graph for a live edit", [&] {
    return E.K == Edit::Kind::Set ? Editor->setArgument(E.Node, E.Arg, E.Value, Diags)
                                  : Editor->rewire(E.Node, E.Arg, E.Value, Diags);
  });
  if (!Ok)
    throw Error("edit '" + E.Text + "': " + firstError(Diags));
  const auto &CG = Editor->compiled();
  EditFacts F;
  F.Structural = Structural;
  if (!KernelShapeHash.empty()) // layout.json from a texcc without kernel.shapeHash: Structural
    F.ShapeChanged = texcc::graph::shapeHash(CG) != KernelShapeHash;
  F.NeedsRebuild = Editor->needsRebuild();
  F.NeedsOnlyStackSlots = Editor->needsOnlyStackSlots();
  F.NeedsAttributeCase = Editor->needsAttributeCase();
  F.NeedsFunction = Editor->needsFunction();
  F.Spill = CG.Spill;
  F.StackSlots = CG.StackSlots;
  F.MaxOutputs = CG.MaxOutputs;
  // A fallback finished on the background thread since the last frame is what a rewiring to a
  // new shape renders with: adopted now, not at the next frame.
  R.adoptFinishedFallback();
  return planEdit(F, Lay.Caps, {R.tierPolicy(), R.fallbackStackSlots(), R.interpStackSlots()});
}

EditResult LiveEditor::apply(const Edit &E, Renderer &R) {
  EditResult Res;
  if (E.K == Edit::Kind::Wait) {
    Res.IdleSeconds = R.waitForBackgroundBuild();
    return Res;
  }
  double T0 = now();
  // inline mode has no editor to validate the edit against: check it on a scratch copy.
  if (!Lay.Caps.ReEncodes)
    if (std::optional<EditProblem> Bad = check({E}))
      throw Error("edit '" + E.Text + "': " + Bad->Message);
  // A refused edit must not stay in the graph that later regenerations hand to texcc.
  texcc::graph::Graph Before = Model;
  EditAction P;
  try {
    P = plan(E, applyToModel(E), R);
  } catch (const Error &) {
    Model = std::move(Before);
    throw;
  }
  switch (P) {
  case EditAction::Upload:
    R.applyArguments(Editor->compiled().ArgsBin, Editor->compiled().Attributes);
    break;
  case EditAction::Regenerate:
    regenerate(R);
    Res.Rebuilt = true;
    break;
  case EditAction::SwitchShapes:
    regenerateInBackground(R);
    Res.Background = true;
    break;
  }
  R.cl().finish();
  Res.Seconds = now() - T0;
  return Res;
}

} // namespace texrender
