// Bump (Bump.h): the built-in signatures and the expansion of graph.json's bump nodes into the
// height evaluated at the hit and at two moved positions.

#include "texcc/Graph/Bump.h"

#include <functional>
#include <map>

namespace texcc::graph {

namespace {

const char *const BuiltinFile = "<texcc>";

FunctionSignature builtin(const std::string &Name, BaseType Return, std::vector<Param> Params,
                          std::vector<std::string> Attributes,
                          std::vector<std::string> Settings = {}) {
  FunctionSignature S;
  S.Name = S.RenamedName = Name;
  S.File = BuiltinFile;
  S.Return = Return;
  S.Params = std::move(Params);
  S.Attributes = std::move(Attributes);
  S.Settings = std::move(Settings);
  return S;
}

Param param(const std::string &Name, BaseType B) { return {Name, ValueType{B, false}}; }

bool isPosition(const std::string &Attr) { return Attr == "WorldPos" || Attr == "ObjectPos"; }

bool readsPosition(const FunctionSignature &Sig) {
  for (const std::string &A : Sig.Attributes)
    if (isPosition(A))
      return true;
  return false;
}

/// The graph with every bump node expanded (Bump.h); Offset and OffsetOf per node of the result.
class BumpExpander {
public:
  BumpExpander(const Graph &G, const SignatureMap &Sigs) : G(G), Sigs(Sigs), X(G) {
    for (size_t I = 0; I < G.Nodes.size(); ++I)
      IndexOf[G.Nodes[I].Id] = static_cast<unsigned>(I);
    Offset.assign(G.Nodes.size(), 0);
    OffsetOf.assign(G.Nodes.size(), "");
    Depends.assign(G.Nodes.size(), -1);
  }

  Graph run() {
    for (size_t I = 0; I < G.Nodes.size(); ++I)
      if (G.Nodes[I].Fn == BumpFunction)
        expandBump(static_cast<unsigned>(I));
    return std::move(X);
  }

  std::vector<unsigned> Offset;
  std::vector<std::string> OffsetOf;

private:
  /// Whether node I's value changes with the position (memoized; the graph is acyclic).
  bool dependsOnPosition(unsigned I) {
    if (Depends[I] >= 0)
      return Depends[I] == 1;
    const Node &N = G.Nodes[I];
    bool D = false;
    auto It = Sigs.find(N.Fn);
    if (It != Sigs.end())
      D = readsPosition(It->second);
    for (const auto &[Name, V] : N.Args) {
      if (V.K == ArgValue::Kind::AttrRef && isPosition(V.Ref))
        D = true;
      else if (V.K == ArgValue::Kind::NodeRef && IndexOf.count(V.Ref))
        D = dependsOnPosition(IndexOf[V.Ref]) || D;
    }
    Depends[I] = D ? 1 : 0;
    return D;
  }

  static std::string suffix(unsigned K) { return K == 1 ? "@dx" : "@dy"; }

  std::string append(Node N, unsigned K, const std::string &Of) {
    std::string Id = N.Id;
    X.Nodes.push_back(std::move(N));
    Offset.push_back(K);
    OffsetOf.push_back(Of);
    return Id;
  }

  /// A node reading the moved position: {"attr": "WorldPos"} inside a copy becomes a node of
  /// texcc_attr_WorldPos, which runs with the copy's offset (an attribute argument is read by
  /// the interpreter from the hit itself).
  std::string positionNode(const ArgValue &Attr, unsigned K) {
    auto Key = std::make_pair(Attr.Ref, K);
    auto It = PositionNodes.find(Key);
    if (It != PositionNodes.end())
      return It->second;
    Node N;
    N.Id = "@" + Attr.Ref + suffix(K);
    N.Fn = Attr.Ref == "WorldPos" ? OffsetWorldPosFunction : OffsetObjectPosFunction;
    N.Loc = N.IdLoc = N.FnLoc = Attr.Loc;
    N.JsonPath = Attr.JsonPath;
    return PositionNodes[Key] = append(std::move(N), K, "");
  }

  /// The copy of position-dependent node I that runs with offset K.
  std::string copyOf(unsigned I, unsigned K) {
    auto Key = std::make_pair(I, K);
    auto It = Copies.find(Key);
    if (It != Copies.end())
      return It->second;
    Node N = G.Nodes[I];
    N.Id += suffix(K);
    for (auto &[Name, V] : N.Args) {
      if (V.K == ArgValue::Kind::AttrRef && isPosition(V.Ref)) {
        std::string Ref = positionNode(V, K);
        V.K = ArgValue::Kind::NodeRef;
        V.Ref = Ref;
      } else if (V.K == ArgValue::Kind::NodeRef && IndexOf.count(V.Ref) &&
                 dependsOnPosition(IndexOf[V.Ref])) {
        V.Ref = copyOf(IndexOf[V.Ref], K);
      }
    }
    return Copies[Key] = append(std::move(N), K, G.Nodes[I].Id);
  }

  void expandBump(unsigned I) {
    X.Nodes[I].Fn = BumpEvalFunction; // copies append to X.Nodes: index, never hold a reference
    const ArgValue *Height = nullptr;
    for (const auto &[Name, V] : G.Nodes[I].Args)
      if (Name == "height")
        Height = &V;
    if (!Height)
      return; // reported by the resolver as a missing argument
    for (unsigned K = 1; K <= 2; ++K) {
      ArgValue Moved = *Height;
      if (Height->K == ArgValue::Kind::NodeRef && IndexOf.count(Height->Ref) &&
          dependsOnPosition(IndexOf[Height->Ref]))
        Moved.Ref = copyOf(IndexOf[Height->Ref], K);
      // The node's own index is stable: copies are appended after every node of G.
      X.Nodes[I].Args.emplace_back(K == 1 ? "heightDx" : "heightDy", std::move(Moved));
    }
  }

  const Graph &G;
  const SignatureMap &Sigs;
  Graph X;
  std::map<std::string, unsigned> IndexOf;
  std::vector<int> Depends;
  std::map<std::pair<unsigned, unsigned>, std::string> Copies;
  std::map<std::pair<std::string, unsigned>, std::string> PositionNodes;
};

} // namespace

SignatureMap withBuiltinSignatures(const SignatureMap &Sigs) {
  SignatureMap All = Sigs;
  const std::vector<std::string> BumpReads = {"GeomNormal", "Normal", "ObjectPos", "WorldPos"};
  std::vector<Param> UserParams = {param("height", BaseType::Float),
                                   param("strength", BaseType::Float),
                                   param("distance", BaseType::Float),
                                   param("normal", BaseType::Float3)};
  std::vector<Param> EvalParams = UserParams;
  EvalParams.push_back(param("heightDx", BaseType::Float));
  EvalParams.push_back(param("heightDy", BaseType::Float));
  FunctionSignature User = builtin(BumpFunction, BaseType::Float3, UserParams, BumpReads,
                                   {"CameraPos"});
  User.RenamedName = BumpEvalFunction;
  All.emplace(BumpFunction, User);
  All.emplace(BumpEvalFunction, builtin(BumpEvalFunction, BaseType::Float3, EvalParams,
                                        BumpReads, {"CameraPos"}));
  All.emplace(OffsetWorldPosFunction,
              builtin(OffsetWorldPosFunction, BaseType::Float3, {}, {"WorldPos"}));
  All.emplace(OffsetObjectPosFunction,
              builtin(OffsetObjectPosFunction, BaseType::Float3, {}, {"ObjectPos"}));
  return All;
}

std::optional<CompiledGraph> resolveWithBump(const Graph &G, const SignatureMap &Sigs,
                                             const CompileOptions &Opts, DiagnosticSink &Diags) {
  std::optional<CompiledGraph> CG = resolveGraph(G, Sigs, Opts, Diags);
  auto Bump = Sigs.find(BumpFunction);
  if (!CG || Bump == Sigs.end() || Bump->second.File != BuiltinFile)
    return CG;
  bool Any = false;
  for (const Node &N : G.Nodes)
    Any |= N.Fn == BumpFunction;
  if (!Any)
    return CG;
  BumpExpander E(G, Sigs);
  const Graph X = E.run();
  // The user's graph was checked above; the expanded one can only repeat its warnings.
  DiagnosticSink Quiet;
  std::optional<CompiledGraph> XG = resolveGraph(X, Sigs, Opts, Quiet);
  if (!XG) {
    for (const Diagnostic &D : Quiet.diagnostics())
      if (D.Level == Diagnostic::Severity::Error)
        Diags.error(D.Loc, "expanding the bump nodes: " + D.Message);
    return std::nullopt;
  }
  for (size_t I = 0; I < XG->Nodes.size(); ++I) {
    XG->Nodes[I].PositionOffset = E.Offset[I];
    XG->Nodes[I].OffsetOf = E.OffsetOf[I];
  }
  return XG;
}

bool usesPositionOffset(const CompiledGraph &CG) {
  for (const CompiledNode &N : CG.Nodes)
    if (N.PositionOffset != 0)
      return true;
  return CG.Signatures.count(BumpEvalFunction) != 0;
}

} // namespace texcc::graph
