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

} // namespace

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

namespace {

/// The typed edit of a set or rewire line; std::nullopt (Diags says why) when its value does not
/// parse.
std::optional<texcc::graph::Edit> typedEdit(const Edit &E, texcc::graph::DiagnosticSink &Diags) {
  if (E.K == Edit::Kind::Rewire)
    return texcc::graph::rewireEdit(E.Node, E.Arg, E.Value);
  std::optional<texcc::graph::ArgValue> V =
      texcc::graph::parseArgValue(E.Node + "." + E.Arg, E.Value, Diags);
  if (!V)
    return std::nullopt;
  texcc::graph::Edit T;
  T.Node = E.Node;
  T.Arg = E.Arg;
  T.Value = std::move(*V);
  return T;
}

/// Whether E changes the wiring of G (a rewiring, a new value of a baked argument or of a node,
/// attribute or image input, or a set to {"attr": ...} or {"node": ...}).
bool changesWiring(const texcc::graph::Graph &G, const texcc::graph::Edit &E) {
  using Kind = texcc::graph::ArgValue::Kind;
  const texcc::graph::Node *N = G.findNode(E.Node);
  const texcc::graph::ArgValue *Was = nullptr;
  if (N)
    for (const auto &[Name, V] : N->Args)
      if (Name == E.Arg)
        Was = &V;
  const bool WasWired = Was && (Was->Bake || !texcc::graph::isConstant(*Was));
  return E.K == texcc::graph::Edit::Kind::Rewire || WasWired || E.Value.K == Kind::NodeRef ||
         E.Value.K == Kind::AttrRef;
}

} // namespace

texcc::graph::Edit graphEdit(const Edit &E) {
  texcc::graph::DiagnosticSink Diags;
  std::optional<texcc::graph::Edit> T = typedEdit(E, Diags);
  if (!T)
    throw Error("edit '" + E.Text + "': " + firstError(Diags));
  return std::move(*T);
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
  carryCommandLineBakes(*G, Lay.Manifest);
  initEditor(std::move(*G));
}

void LiveEditor::initEditor(texcc::graph::Graph G) {
  KernelShapeHash = Lay.ShapeHash;
  // Every mode has one: where the values are literals of the kernel (inline), it validates the
  // edit that a regeneration then compiles.
  Editor = makeEditor(std::move(G));
}

const texcc::graph::Graph &LiveEditor::graph() const { return Editor->graph(); }

void LiveEditor::markCommandLineBakes(texcc::graph::Graph &G) const {
  carryCommandLineBakes(G, Lay.Manifest);
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

std::optional<EditProblem> LiveEditor::check(std::vector<Edit> Edits,
                                             std::vector<CheckedEdit> &Checked) const {
  Checked.clear();
  Checked.reserve(Edits.size()); // Last points into it
  const texcc::graph::CheckedEdit *Last = nullptr; // the edit the next is checked after
  for (size_t I = 0; I < Edits.size(); ++I) {
    CheckedEdit C(std::move(Edits[I]));
    if (C.Line.K != Edit::Kind::Wait) {
      const texcc::graph::Graph &Base = Last ? Last->graph() : graph();
      texcc::graph::DiagnosticSink Diags;
      std::optional<texcc::graph::Edit> T = typedEdit(C.Line, Diags);
      if (T) {
        C.Wiring = changesWiring(Base, *T);
        C.Checked = Last ? Editor->check(*Last, *T, Diags) : Editor->check(*T, Diags);
      }
      if (!C.Checked)
        return EditProblem{I, columnAtFault(Base, C.Line), firstError(Diags)};
    }
    Checked.push_back(std::move(C));
    if (Checked.back().Checked)
      Last = &*Checked.back().Checked;
  }
  return std::nullopt;
}

unsigned LiveEditor::columnAtFault(const texcc::graph::Graph &Base, const Edit &E) const {
  const texcc::graph::Node *N = Base.findNode(E.Node);
  if (!N)
    return E.NodeCol;
  // Every function a node of the graph names has its signature in the compiled graph.
  const auto &Sigs = Editor->compiled().Signatures;
  auto Sig = Sigs.find(N->Fn);
  if (Sig != Sigs.end() &&
      std::none_of(Sig->second.Params.begin(), Sig->second.Params.end(),
                   [&](const texcc::graph::Param &P) { return P.Name == E.Arg; }))
    return E.ArgCol;
  return E.ValueCol;
}

LiveEditor::~LiveEditor() = default;

texcc::graph::Graph LiveEditor::absoluteGraph() const {
  fs::path GraphDir = fs::path(Lay.GraphPath).parent_path();
  texcc::graph::Graph G = graph();
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
  texcc::graph::Graph G = graph();
  Lay = New;
  Lay.GraphPath = Original;
  std::unique_ptr<texcc::graph::GraphEditor> Old = std::move(Editor);
  initEditor(std::move(G));
  // Edits checked against the old editor (texrender's edit script) apply to the new one
  // without being validated again: the same graph, the same sources' signatures.
  Editor->continueFrom(*Old);
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
  Switching = true;
  R.switchShapes(
      CG.ArgsBin, CG.Attributes, [Files] { return Files->run(); },
      [this, Files](Layout &New) {
        adopt(New, *Files);
        New.ArgsBin = Editor->compiled().ArgsBin;
        New.Attributes = Editor->compiled().Attributes;
        Switching = false; // the renderer switches to New with them
      });
}

void LiveEditor::Pending::add(bool Wiring, const texcc::graph::GraphEditor &Ed) {
  // What the kernel lacks accumulates over a batch: a later edit re-encoded in place does not
  // make an earlier one's new function or deeper stack runnable.
  Structural |= Wiring;
  NeedsRebuild |= Ed.needsRebuild();
  NeedsCode |= Ed.needsRebuild() && !Ed.needsOnlyStackSlots();
  NeedsAttributeCase |= Ed.needsAttributeCase();
  NeedsFunction |= Ed.needsFunction();
}

EditAction LiveEditor::plan(const Pending &P, Renderer &R) {
  if (!Lay.Caps.ReEncodes)
    return planEdit({}, Lay.Caps, {});
  const auto &CG = Editor->compiled();
  EditFacts F;
  F.Structural = P.Structural;
  if (!KernelShapeHash.empty()) // layout.json from a texcc without kernel.shapeHash: Structural
    F.ShapeChanged = texcc::graph::shapeHash(CG) != KernelShapeHash;
  F.NeedsRebuild = P.NeedsRebuild;
  F.NeedsOnlyStackSlots = P.NeedsRebuild && !P.NeedsCode;
  F.NeedsAttributeCase = P.NeedsAttributeCase;
  F.NeedsFunction = P.NeedsFunction;
  F.Spill = CG.Spill;
  F.StackSlots = CG.StackSlots;
  F.MaxOutputs = CG.MaxOutputs;
  // A fallback finished on the background thread since the last frame is what a rewiring to a
  // new shape renders with: adopted now (between passes), not at the next frame.
  TierManager &T = R.tiers();
  T.collect(/*Rest=*/true);
  return planEdit(F, Lay.Caps, {R.tierPolicy(), T.fallbackStackSlots(), T.interpStackSlots()});
}

EditResult LiveEditor::carryOut(const Pending &P, Renderer &R, double T0) {
  EditResult Res;
  Rendered = false; // the graph editor has the edit; the renderer has it once this is done
  switch (plan(P, R)) {
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
  Rendered = true; // Lay's kernel, or the fallback while Switching
  Res.Seconds = now() - T0;
  return Res;
}

std::optional<Layout> LiveEditor::renderedLayout() const {
  if (!Rendered || Switching)
    return std::nullopt;
  Layout L = Lay;
  // A kernel that re-encodes runs the graph editor's args.bin (uploaded after each edit, and
  // given to a shape kernel adopted later); an inline kernel is regenerated at every edit, and
  // Lay has its args.bin.
  if (L.Caps.ReEncodes) {
    L.ArgsBin = Editor->compiled().ArgsBin;
    L.Attributes = Editor->compiled().Attributes;
  }
  return L;
}

EditResult LiveEditor::apply(const Edit &E, Renderer &R) {
  if (E.K == Edit::Kind::Wait) {
    EditResult Res;
    Res.IdleSeconds = R.tiers().waitForBackgroundBuild();
    return Res;
  }
  return apply(graphEdit(E), R, E.Text);
}

EditResult LiveEditor::apply(CheckedEdit C, Renderer &R) {
  if (!C.Checked)
    return apply(C.Line, R); // a wait
  double T0 = now();
  Pending P;
  bool Applied = texcc::whileAllocating("encoding the graph for a live edit",
                                        [&] { return Editor->apply(std::move(*C.Checked)); });
  if (!Applied) {
    // Checked against another graph than the one rendered (the edits applied out of the order
    // they were checked in, or a kernel regenerated from changed sources): validated here.
    return apply(C.Checked->edit(), R, C.Line.Text);
  }
  P.add(C.Wiring, *Editor);
  return carryOut(P, R, T0);
}

EditResult LiveEditor::apply(const texcc::graph::Edit &E, Renderer &R, const std::string &Text) {
  double T0 = now();
  Pending P;
  const bool Wiring = changesWiring(graph(), E);
  texcc::graph::DiagnosticSink Diags;
  // The editor validates and applies it, or leaves everything as it was.
  if (!texcc::whileAllocating("encoding the graph for a live edit",
                              [&] { return Editor->apply(E, Diags); }))
    throw Error("edit '" + (Text.empty() ? texcc::graph::editText(E) : Text) +
                "': " + firstError(Diags));
  P.add(Wiring, *Editor);
  return carryOut(P, R, T0);
}

EditResult LiveEditor::apply(const std::vector<texcc::graph::Edit> &Edits, Renderer &R) {
  if (Edits.size() == 1)
    return apply(Edits[0], R);
  double T0 = now();
  Pending P;
  // The edits go to a copy of the editor, which replaces it once all are applied.
  std::unique_ptr<texcc::graph::GraphEditor> Next;
  texcc::whileAllocating("encoding the graph for a live edit", [&] {
    Next = std::make_unique<texcc::graph::GraphEditor>(*Editor);
    std::swap(Next, Editor);
    for (const texcc::graph::Edit &E : Edits) {
      const bool Wiring = changesWiring(graph(), E);
      texcc::graph::DiagnosticSink Diags;
      if (!Editor->apply(E, Diags)) {
        std::swap(Next, Editor);
        throw Error("edit '" + texcc::graph::editText(E) + "': " + firstError(Diags));
      }
      P.add(Wiring, *Editor);
    }
    return true;
  });
  return carryOut(P, R, T0);
}

} // namespace texrender
