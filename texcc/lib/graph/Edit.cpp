// Live edits (GraphEditor): a parameter edit patches args.bin in place when it can; anything
// else recompiles the graph with the kernel's function ids pinned.

#include "texcc/Graph/Edit.h"
#include "texcc/Graph/Bump.h"
#include "texcc/Graph/Passes.h"
#include "texcc/OutOfMemory.h"

#include "Json.h"

#include <algorithm>
#include <atomic>

namespace texcc::graph {

namespace {

void forward(const DiagnosticSink &From, DiagnosticSink &To, bool ErrorsOnly) {
  for (const Diagnostic &D : From.diagnostics()) {
    switch (D.Level) {
    case Diagnostic::Severity::Error:
      To.error(D.Loc, D.Message);
      break;
    case Diagnostic::Severity::Warning:
      if (!ErrorsOnly)
        To.warning(D.Loc, D.Message);
      break;
    case Diagnostic::Severity::Note:
      if (!ErrorsOnly)
        To.note(D.Loc, D.Message);
      break;
    }
  }
}

/// Sets (or adds) NODE.ARG in a copy of the graph.
ArgValue *argumentOf(Node &N, const std::string &Arg) {
  for (auto &KV : N.Args)
    if (KV.first == Arg)
      return &KV.second;
  N.Args.emplace_back(Arg, ArgValue());
  return &N.Args.back().second;
}

std::atomic<uint64_t> States{0};      // the last graph state numbered
std::atomic<uint64_t> Validations{0}; // GraphEditor::check's edits

uint64_t newState() { return ++States; }

/// Whether A and B validate edits of G alike: the same return and parameters (names and types)
/// for every function a node of G names (edits never change a node's function).
bool validateAlike(const Graph &G, const SignatureMap &A, const SignatureMap &B) {
  for (const Node &N : G.Nodes) {
    auto I = A.find(N.Fn), J = B.find(N.Fn);
    if ((I == A.end()) != (J == B.end()))
      return false;
    if (I == A.end())
      continue;
    const FunctionSignature &X = I->second, &Y = J->second;
    if (X.Return != Y.Return || X.Params.size() != Y.Params.size())
      return false;
    for (size_t K = 0; K < X.Params.size(); ++K)
      if (X.Params[K].Name != Y.Params[K].Name || !(X.Params[K].Type == Y.Params[K].Type))
        return false;
  }
  return true;
}

} // namespace

Edit CheckedEdit::edit() const {
  Edit E;
  E.K = K;
  E.Node = NodeId;
  E.Arg = Arg;
  if (const Node *N = Edited.findNode(NodeId))
    for (const auto &[Name, V] : N->Args)
      if (Name == Arg)
        E.Value = V;
  return E;
}

GraphEditor::GraphEditor(Graph G, SignatureMap Sigs, CompileOptions Opts)
    : G(std::move(G)), Sigs(std::move(Sigs)), Opts(std::move(Opts)), State(newState()) {}

uint64_t GraphEditor::validations() { return Validations.load(); }

bool GraphEditor::continueFrom(const GraphEditor &Old) {
  if (!sameGraph(G, Old.G) || !validateAlike(G, Sigs, Old.Sigs))
    return false;
  State = Old.State;
  return true;
}

bool GraphEditor::init(DiagnosticSink &Diags) {
  std::optional<CompiledGraph> C = compileGraph(G, Sigs, Opts, Diags);
  if (!C)
    return false;
  CG = std::move(*C);
  KernelStackSlots = CG.StackSlots;
  KernelMaxOutputs = CG.MaxOutputs;
  KernelArgumentAttributes = CG.GraphArgumentAttributes;
  // The kernel has a switch case for exactly these functions; later compiles keep their ids.
  if (Opts.FixedFunctionIds.empty())
    for (size_t Id = 0; Id < CG.FunctionsById.size(); ++Id)
      if (!CG.FunctionsById[Id].empty())
        Opts.FixedFunctionIds[CG.FunctionsById[Id]] = static_cast<unsigned>(Id);
  // Its quickened opcodes are Opts.Quickened (the graph library never chooses others, whose
  // cases the kernel would lack): later compiles apply the same table.
  NeedsRebuild = NeedsCode = NeedsAttributeCase = NeedsFunction = false;
  return true;
}

void GraphEditor::recompile(CompiledGraph Resolved) {
  CG = compileResolved(std::move(Resolved), Sigs, Opts);
  NeedsCode = CG.MaxOutputs > KernelMaxOutputs;
  NeedsFunction = false;
  for (const CompiledNode &N : CG.Nodes) {
    NeedsFunction |= !Opts.FixedFunctionIds.count(N.Fn);
    if (Opts.InterpHoistedCalls)
      for (unsigned P : CG.Signatures.at(N.Fn).HoistedFrom)
        NeedsCode |= P >= N.Args.size() || N.Args[P].Src != CompiledArg::Source::Constant;
  }
  NeedsAttributeCase = !std::includes(
      KernelArgumentAttributes.begin(), KernelArgumentAttributes.end(),
      CG.GraphArgumentAttributes.begin(), CG.GraphArgumentAttributes.end());
  NeedsCode |= NeedsAttributeCase || NeedsFunction;
  NeedsRebuild = NeedsCode || CG.StackSlots > KernelStackSlots;
}

/// The node NodeId of G, or nullptr after an error naming the closest id.
static const Node *findNodeOrSay(const Graph &G, const std::string &NodeId,
                                 DiagnosticSink &Diags) {
  if (const Node *N = G.findNode(NodeId))
    return N;
  std::vector<std::string> Ids;
  for (const Node &Other : G.Nodes)
    Ids.push_back(Other.Id);
  std::string Near = json::closestMatch(NodeId, Ids);
  Diags.error({}, "unknown node '" + NodeId + "'" +
                      (Near.empty() ? "" : "; did you mean '" + Near + "'?"));
  return nullptr;
}

bool GraphEditor::setArgument(const std::string &NodeId, const std::string &Arg,
                              const std::string &Value, DiagnosticSink &Diags) {
  if (!findNodeOrSay(G, NodeId, Diags))
    return false;
  std::optional<ArgValue> V = parseArgValue(NodeId + "." + Arg, Value, Diags);
  return V && setArgument(NodeId, Arg, std::move(*V), Diags);
}

bool GraphEditor::setArgument(const std::string &NodeId, const std::string &Arg, ArgValue V,
                              DiagnosticSink &Diags) {
  Edit E;
  E.Node = NodeId;
  E.Arg = Arg;
  E.Value = std::move(V);
  return apply(E, Diags);
}

bool GraphEditor::rewire(const std::string &NodeId, const std::string &Arg,
                         const std::string &SourceNode, DiagnosticSink &Diags) {
  return apply(rewireEdit(NodeId, Arg, SourceNode), Diags);
}

bool GraphEditor::apply(const Edit &E, DiagnosticSink &Diags) {
  std::optional<CheckedEdit> C = check(E, Diags);
  return C && apply(std::move(*C));
}

std::optional<CheckedEdit> GraphEditor::check(const Edit &E, DiagnosticSink &Diags) const {
  return checkAgainst(G, State, E, Diags);
}

std::optional<CheckedEdit> GraphEditor::check(const CheckedEdit &After, const Edit &E,
                                              DiagnosticSink &Diags) const {
  return checkAgainst(After.Edited, After.Result, E, Diags);
}

std::optional<CheckedEdit> GraphEditor::checkAgainst(const Graph &Base, uint64_t BaseState,
                                                     const Edit &E, DiagnosticSink &Diags) const {
  ++Validations;
  const bool Rewire = E.K == Edit::Kind::Rewire;
  const Node *N = Rewire ? Base.findNode(E.Node) : findNodeOrSay(Base, E.Node, Diags);
  if (!N) {
    if (Rewire)
      Diags.error({}, "unknown node '" + E.Node + "'");
    return std::nullopt;
  }
  CheckedEdit C;
  C.K = E.K;
  C.NodeId = E.Node;
  C.Arg = E.Arg;
  C.Base = BaseState;
  C.Edited = Base;
  ArgValue *Slot = argumentOf(*C.Edited.findNode(E.Node), E.Arg);
  ArgValue V = E.Value;
  if (Rewire) {
    V = ArgValue();
    V.K = ArgValue::Kind::NodeRef;
    V.Ref = E.Value.Ref;
    V.Loc = {E.Node + "." + E.Arg, 0, 0};
  } else {
    V.Bake |= Slot->Bake; // a new value of a baked argument stays baked
  }
  V.KeyLoc = Slot->KeyLoc;
  V.JsonPath = N->JsonPath + "/args/" + E.Arg;
  *Slot = std::move(V);
  // The edited graph resolved as compileGraph resolves it; only its errors are kept (its
  // warnings were given when the graph was compiled).
  DiagnosticSink Check;
  std::optional<CompiledGraph> Resolved =
      whileAllocating("building the node and material tables", [&] {
        return resolveWithBump(C.Edited, withBuiltinSignatures(Sigs), Opts, Check);
      });
  forward(Check, Diags, /*ErrorsOnly=*/true);
  if (!Resolved)
    return std::nullopt;
  C.Resolved = std::move(*Resolved);
  C.Result = newState();
  return C;
}

bool GraphEditor::apply(CheckedEdit &&C) {
  if (C.Base != State)
    return false;
  State = C.Result;
  const bool Patched = C.K == Edit::Kind::Set && patchInPlace(C);
  G = std::move(C.Edited);
  if (Patched)
    NeedsRebuild = NeedsCode = NeedsAttributeCase = NeedsFunction = false;
  else
    recompile(std::move(C.Resolved));
  return true;
}

bool GraphEditor::patchInPlace(const CheckedEdit &C) {
  int Live = CG.findNode(C.NodeId);
  if (Live < 0 || CG.Nodes[Live].Id != C.NodeId || !CG.Nodes[Live].MergedIds.empty())
    return false;
  // Resolved's nodes are the edited graph's, in its order (bump's copies after them).
  size_t GraphIndex = static_cast<size_t>(C.Edited.findNode(C.NodeId) - C.Edited.Nodes.data());
  CompiledNode &CN = CG.Nodes[Live];
  const std::vector<CompiledArg> &NewArgs = C.Resolved.Nodes[GraphIndex].Args;
  for (size_t I = 0; I < CN.Args.size() && I < NewArgs.size(); ++I) {
    CompiledArg &Old = CN.Args[I];
    const CompiledArg &New = NewArgs[I];
    if (Old.Name != C.Arg)
      continue;
    if (Old.Src != CompiledArg::Source::Constant || New.Src != Old.Src ||
        New.Values.size() != Old.Values.size() || New.ArrayCount != Old.ArrayCount)
      return false;
    Old.Values = New.Values;
    encodeArgumentValue(CG.ArgsBin, parameterBlockStart(CN, CN.RecordOffset), Old);
    for (uint32_t Copy : CN.RecordCopies)
      encodeArgumentValue(CG.ArgsBin, parameterBlockStart(CN, Copy), Old);
    for (CompiledNode &Moved : CG.Nodes) // bump's copies of the node (Bump.h) follow it
      if (Moved.OffsetOf == C.NodeId && I < Moved.Args.size()) {
        Moved.Args[I].Values = New.Values;
        encodeArgumentValue(CG.ArgsBin, parameterBlockStart(Moved, Moved.RecordOffset), Old);
        for (uint32_t Copy : Moved.RecordCopies)
          encodeArgumentValue(CG.ArgsBin, parameterBlockStart(Moved, Copy), Old);
      }
    if (!CG.Quickened.empty() && argumentSource(Old).K == ArgumentSource::Kind::IntValue) {
      // An int value is part of a quickened pattern: the instruction now runs the entry of
      // the kernel's table (pinned by init) for its new value, or its plain case (a new
      // opcode word).
      applyQuickened(CG, Opts.Quickened, nullptr);
      encodeArgsBin(CG);
    }
    return true;
  }
  return false;
}

} // namespace texcc::graph
