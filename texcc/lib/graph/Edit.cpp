// Live edits (GraphEditor): a parameter edit patches args.bin in place when it can; anything
// else recompiles the graph with the kernel's function ids pinned.

#include "texcc/Graph/Edit.h"
#include "texcc/Graph/Passes.h"

#include "Json.h"

#include <algorithm>

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

} // namespace

GraphEditor::GraphEditor(Graph G, SignatureMap Sigs, CompileOptions Opts)
    : G(std::move(G)), Sigs(std::move(Sigs)), Opts(std::move(Opts)) {}

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

bool GraphEditor::recompile(DiagnosticSink &Diags) {
  std::optional<CompiledGraph> C = compileGraph(G, Sigs, Opts, Diags);
  if (!C)
    return false;
  CG = std::move(*C);
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
  return true;
}

/// The node NodeId of G, or nullptr after an error naming the closest id.
static Node *findNodeOrSay(Graph &G, const std::string &NodeId, DiagnosticSink &Diags) {
  if (Node *N = G.findNode(NodeId))
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

bool GraphEditor::apply(const Edit &E, DiagnosticSink &Diags) {
  if (E.K == Edit::Kind::Rewire)
    return rewire(E.Node, E.Arg, E.Value.Ref, Diags);
  return setArgument(E.Node, E.Arg, E.Value, Diags);
}

bool GraphEditor::setArgument(const std::string &NodeId, const std::string &Arg, ArgValue V,
                              DiagnosticSink &Diags) {
  Node *N = findNodeOrSay(G, NodeId, Diags);
  if (!N)
    return false;
  Graph Edited = G;
  ArgValue *Slot = argumentOf(*Edited.findNode(NodeId), Arg);
  V.KeyLoc = Slot->KeyLoc;
  V.Bake |= Slot->Bake; // a new value of a baked argument stays baked
  V.JsonPath = N->JsonPath + "/args/" + Arg;
  *Slot = std::move(V);

  // Validate the edited graph; keep only its errors (warnings were given at compile time).
  DiagnosticSink Check;
  std::optional<CompiledGraph> Resolved = resolveGraph(Edited, Sigs, Opts, Check);
  forward(Check, Diags, /*ErrorsOnly=*/true);
  if (!Resolved)
    return false;

  // The fast path: a live, unmerged node whose constant keeps its shape is patched in place.
  int Live = CG.findNode(NodeId);
  size_t GraphIndex = static_cast<size_t>(N - G.Nodes.data());
  if (Live >= 0 && CG.Nodes[Live].Id == NodeId && CG.Nodes[Live].MergedIds.empty()) {
    CompiledNode &CN = CG.Nodes[Live];
    const std::vector<CompiledArg> &NewArgs = Resolved->Nodes[GraphIndex].Args;
    for (size_t I = 0; I < CN.Args.size() && I < NewArgs.size(); ++I) {
      CompiledArg &Old = CN.Args[I];
      const CompiledArg &New = NewArgs[I];
      if (Old.Name != Arg)
        continue;
      if (Old.Src != CompiledArg::Source::Constant || New.Src != Old.Src ||
          New.Values.size() != Old.Values.size() || New.ArrayCount != Old.ArrayCount)
        break;
      Old.Values = New.Values;
      encodeArgumentValue(CG.ArgsBin, parameterBlockStart(CN, CN.RecordOffset), Old);
      for (uint32_t Copy : CN.RecordCopies)
        encodeArgumentValue(CG.ArgsBin, parameterBlockStart(CN, Copy), Old);
      for (CompiledNode &Moved : CG.Nodes) // bump's copies of the node (Bump.h) follow it
        if (Moved.OffsetOf == NodeId && I < Moved.Args.size()) {
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
      G = std::move(Edited);
      NeedsRebuild = NeedsCode = NeedsAttributeCase = NeedsFunction = false;
      return true;
    }
  }
  Graph Saved = std::move(G);
  G = std::move(Edited);
  if (recompile(Diags))
    return true;
  G = std::move(Saved);
  return false;
}

bool GraphEditor::rewire(const std::string &NodeId, const std::string &Arg,
                         const std::string &SourceNode, DiagnosticSink &Diags) {
  if (!G.findNode(NodeId)) {
    Diags.error({}, "unknown node '" + NodeId + "'");
    return false;
  }
  Graph Saved = G;
  Node *N = G.findNode(NodeId);
  ArgValue *Slot = argumentOf(*N, Arg);
  ArgValue V;
  V.K = ArgValue::Kind::NodeRef;
  V.Ref = SourceNode;
  V.Loc = {NodeId + "." + Arg, 0, 0};
  V.KeyLoc = Slot->KeyLoc;
  V.JsonPath = N->JsonPath + "/args/" + Arg;
  *Slot = std::move(V);
  if (recompile(Diags))
    return true;
  G = std::move(Saved);
  return false;
}

} // namespace texcc::graph
