// Validation of a parsed graph against the function signatures: resolveGraph() turns every
// node argument and BSDF input into a CompiledArg / CompiledBsdfInput, or reports why not.

#include "texcc/Graph/Bump.h"
#include "texcc/Graph/Passes.h"
#include "texcc/Support/Numbers.h"

#include "Json.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace texcc::graph {

namespace {

std::string withPath(const std::string &Msg, const std::string &JsonPath) {
  return Msg + " [" + (JsonPath.empty() ? "/" : JsonPath) + "]";
}

std::string numberList(const std::vector<double> &V) {
  std::string S = "[";
  for (size_t I = 0; I < V.size(); ++I)
    S += (I ? ", " : "") + json::formatNumber(V[I]);
  return S + "]";
}

class Resolver {
public:
  Resolver(const Graph &G, const SignatureMap &Sigs, const CompileOptions &Opts,
           DiagnosticSink &Diags)
      : G(G), Sigs(Sigs), Opts(Opts), Diags(Diags) {}

  std::optional<CompiledGraph> run() {
    CG.GraphPath = G.Path;
    CG.Sources = G.Sources;
    CG.Images = G.Images;
    CG.ImageColorSpaces = G.ImageColorSpaces;
    for (size_t I = 0; I < G.Nodes.size(); ++I)
      IndexOf[G.Nodes[I].Id] = static_cast<unsigned>(I);
    for (const Node &N : G.Nodes)
      resolveNode(N);
    for (const Material &M : G.Materials)
      resolveMaterial(M);
    if (Diags.hasErrors())
      return std::nullopt;
    if (!checkCycles())
      return std::nullopt;
    warnUnused();
    recordGraphFunctions();
    return std::move(CG);
  }

private:
  /// What every node needs of an interpreter, before the passes drop the dead ones.
  void recordGraphFunctions() {
    std::set<int> Attrs;
    for (const CompiledNode &N : CG.Nodes) {
      if (std::find(CG.GraphFunctions.begin(), CG.GraphFunctions.end(), N.Fn) ==
          CG.GraphFunctions.end())
        CG.GraphFunctions.push_back(N.Fn);
      for (const CompiledArg &A : N.Args)
        if (A.Src == CompiledArg::Source::Attribute)
          Attrs.insert(A.AttrId);
    }
    CG.GraphArgumentAttributes.assign(Attrs.begin(), Attrs.end());
  }

  void error(const SourceLoc &L, const std::string &Msg, const std::string &JsonPath) {
    Diags.error(L, withPath(Msg, JsonPath));
  }

  const FunctionSignature *signatureOf(unsigned NodeIndex) const {
    auto It = Sigs.find(G.Nodes[NodeIndex].Fn);
    return It == Sigs.end() ? nullptr : &It->second;
  }

  void reportUnknownFunction(const Node &N) {
    std::vector<std::string> Candidates = Opts.KnownFunctions;
    for (const auto &KV : Sigs)
      Candidates.push_back(KV.first);
    bool Known = false;
    for (const std::string &K : Opts.KnownFunctions)
      Known |= K == N.Fn;
    std::string Msg;
    if (Known) {
      Msg = "node '" + N.Id + "': function '" + N.Fn +
            "' is not a texture function (it must return float..float4 and take only float, "
            "int, float2..4, sam2D or __global const T* parameters)";
    } else {
      Msg = "node '" + N.Id + "': unknown function '" + N.Fn + "'";
      std::string Near = json::closestMatch(N.Fn, Candidates);
      auto Library = Opts.LibraryFunctions.find(N.Fn);
      if (Library != Opts.LibraryFunctions.end())
        Msg += " (defined in " + Library->second + ": add it to \"sources\")";
      else if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
    }
    error(N.FnLoc, Msg, N.JsonPath + "/fn");
  }

  void resolveNode(const Node &N) {
    CompiledNode CN;
    CN.Id = N.Id;
    CN.Fn = N.Fn;
    CN.Loc = N.IdLoc.Line ? N.IdLoc : N.Loc;
    auto It = Sigs.find(N.Fn);
    if (It == Sigs.end()) {
      reportUnknownFunction(N);
      CG.Nodes.push_back(std::move(CN));
      return;
    }
    const FunctionSignature &Sig = It->second;
    CN.Return = Sig.Return;
    std::vector<std::string> ParamNames;
    for (const Param &P : Sig.Params)
      ParamNames.push_back(P.Name);
    for (const auto &[Name, Value] : N.Args) {
      bool Known = false;
      for (const Param &P : Sig.Params)
        Known |= P.Name == Name;
      if (Known)
        continue;
      std::string Msg = "node '" + N.Id + "': unknown argument '" + Name + "' for '" + N.Fn + "'";
      std::string Near = json::closestMatch(Name, ParamNames);
      if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
      else
        Msg += ParamNames.empty() ? "; it takes no parameters"
                                  : "; its parameters are " + json::quotedList(ParamNames);
      error(Value.KeyLoc.Line ? Value.KeyLoc : Value.Loc, Msg, Value.JsonPath);
    }
    for (const Param &P : Sig.Params) {
      const ArgValue *A = nullptr;
      for (const auto &KV : N.Args)
        if (KV.first == P.Name)
          A = &KV.second;
      if (!A) {
        error(N.Loc,
              "node '" + N.Id + "': missing argument '" + P.Name + "' (" + spelling(P.Type) +
                  ") of '" + N.Fn + "'",
              N.JsonPath);
        continue;
      }
      CompiledArg CA;
      if (resolveArg(N, P, *A, CA))
        CN.Args.push_back(std::move(CA));
    }
    CG.Nodes.push_back(std::move(CN));
  }

  std::string describeFound(const ArgValue &A) {
    switch (A.K) {
    case ArgValue::Kind::Number:
      return "a number";
    case ArgValue::Kind::Vector:
      return "a vector of " + std::to_string(A.Numbers.size()) + " numbers";
    case ArgValue::Kind::Array:
      if (A.IsArrayOfRows)
        return "an array of " + std::to_string(A.Rows.size()) + " rows";
      return "an array of " + std::to_string(A.Numbers.size()) + " numbers";
    case ArgValue::Kind::NodeRef: {
      auto It = IndexOf.find(A.Ref);
      const FunctionSignature *S = It == IndexOf.end() ? nullptr : signatureOf(It->second);
      return "node '" + A.Ref + "'" + (S ? " of type " + spelling(S->Return) : "");
    }
    case ArgValue::Kind::AttrRef: {
      int Id = attributeId(A.Ref);
      return "attribute '" + A.Ref + "'" +
             (Id >= 0 ? " of type " + spelling(attributeTable()[Id].second) : "");
    }
    case ArgValue::Kind::ImageRef:
      return "image '" + A.Ref + "' (sam2D)";
    }
    return "a value";
  }

  bool mismatch(const Node &N, const Param &P, const ArgValue &A, const std::string &Why = "") {
    error(A.Loc,
          "node '" + N.Id + "': argument '" + P.Name + "' expects " + spelling(P.Type) +
              ", got " + describeFound(A) + Why,
          A.JsonPath);
    return false;
  }

  bool resolveNodeRef(const std::string &What, const ArgValue &A, unsigned &Index) {
    auto It = IndexOf.find(A.Ref);
    if (It != IndexOf.end()) {
      Index = It->second;
      return true;
    }
    std::vector<std::string> Ids;
    for (const Node &Other : G.Nodes)
      Ids.push_back(Other.Id);
    std::string Msg = What + " refers to unknown node '" + A.Ref + "'";
    std::string Near = json::closestMatch(A.Ref, Ids);
    if (!Near.empty())
      Msg += "; did you mean '" + Near + "'?";
    error(A.Loc, Msg, A.JsonPath);
    return false;
  }

  bool resolveArray(const Node &N, const Param &P, const ArgValue &A, CompiledArg &CA) {
    unsigned Comp = componentCount(P.Type.Base);
    bool Flat = A.K == ArgValue::Kind::Vector || (A.K == ArgValue::Kind::Array && !A.IsArrayOfRows);
    if (Comp == 1) {
      if (!Flat)
        return mismatch(N, P, A, A.K == ArgValue::Kind::Array
                                     ? " (an array of numbers is expected)"
                                     : "");
      CA.Values = A.Numbers;
      CA.ArrayCount = static_cast<unsigned>(A.Numbers.size());
    } else {
      bool Empty = Flat && A.Numbers.empty();
      if (!Empty && !(A.K == ArgValue::Kind::Array && A.IsArrayOfRows))
        return mismatch(N, P, A, " (an array of " + spelling(P.Type.Base) + " rows is expected)");
      for (size_t R = 0; R < A.Rows.size(); ++R) {
        if (A.Rows[R].size() != Comp)
          return mismatch(N, P, A,
                          "; row " + std::to_string(R) + " has " +
                              std::to_string(A.Rows[R].size()) + " numbers, not " +
                              std::to_string(Comp));
        CA.Values.insert(CA.Values.end(), A.Rows[R].begin(), A.Rows[R].end());
      }
      CA.ArrayCount = static_cast<unsigned>(A.Rows.size());
    }
    if (P.Type.Base == BaseType::Int)
      for (double V : CA.Values)
        if (!texcc::fitsInInt32(V))
          return mismatch(N, P, A, "; element " + json::formatNumber(V) + " is not an int");
    return true;
  }

  bool resolveConstant(const Node &N, const Param &P, const ArgValue &A, CompiledArg &CA) {
    BaseType B = P.Type.Base;
    CA.Bake = A.Bake;
    if (B == BaseType::Sampler)
      return mismatch(N, P, A, "; bind an image with {\"image\": name}");
    if (A.K == ArgValue::Kind::Number) {
      double V = A.Numbers.front();
      if (B == BaseType::Int && V != std::floor(V))
        return mismatch(N, P, A, " (" + json::formatNumber(V) + " is not an int)");
      if (B == BaseType::Int && !texcc::fitsInInt32(V))
        return mismatch(N, P, A, " (" + json::formatNumber(V) + " is outside the 32-bit int range)");
      CA.Values.assign(componentCount(B), V);
      return true;
    }
    // A vector literal: exactly the parameter's width.
    if (B == BaseType::Int || componentCount(B) != A.Numbers.size())
      return mismatch(N, P, A, " " + numberList(A.Numbers));
    CA.Values = A.Numbers;
    return true;
  }

  bool resolveArg(const Node &N, const Param &P, const ArgValue &A, CompiledArg &CA) {
    CA.Name = P.Name;
    CA.Type = P.Type;
    if (P.Type.IsGlobalArray) {
      if (A.K != ArgValue::Kind::Vector && A.K != ArgValue::Kind::Array)
        return mismatch(N, P, A);
      if (A.Bake) {
        error(A.Loc,
              "node '" + N.Id + "': argument '" + P.Name + "' (" + spelling(P.Type) +
                  ") cannot be baked; arrays stay in the fake stack",
              A.JsonPath);
        return false;
      }
      return resolveArray(N, P, A, CA);
    }
    switch (A.K) {
    case ArgValue::Kind::Number:
    case ArgValue::Kind::Vector:
      return resolveConstant(N, P, A, CA);
    case ArgValue::Kind::Array:
      return mismatch(N, P, A);
    case ArgValue::Kind::ImageRef: {
      if (P.Type.Base != BaseType::Sampler)
        return mismatch(N, P, A);
      for (size_t I = 0; I < G.Images.size(); ++I)
        if (G.Images[I].first == A.Ref) {
          CA.Values = {static_cast<double>(I)};
          return true;
        }
      std::vector<std::string> Names;
      for (const auto &Img : G.Images)
        Names.push_back(Img.first);
      std::string Msg = "node '" + N.Id + "': unknown image '" + A.Ref + "'";
      std::string Near = json::closestMatch(A.Ref, Names);
      if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
      else
        Msg += Names.empty() ? "; the graph declares no \"images\""
                             : "; the images are " + json::quotedList(Names);
      error(A.Loc, Msg, A.JsonPath);
      return false;
    }
    case ArgValue::Kind::AttrRef: {
      int Id = attributeId(A.Ref);
      if (Id < 0) {
        std::vector<std::string> Names;
        for (const auto &KV : attributeTable())
          Names.push_back(KV.first);
        std::string Msg = "node '" + N.Id + "': unknown attribute '" + A.Ref + "'";
        std::string Near = json::closestMatch(A.Ref, Names);
        Msg += Near.empty() ? "; the attributes are " + json::quotedList(Names)
                            : "; did you mean '" + Near + "'?";
        error(A.Loc, Msg, A.JsonPath);
        return false;
      }
      BaseType From = attributeTable()[Id].second;
      if (!isAssignable(From, P.Type))
        return mismatch(N, P, A);
      CA.Src = CompiledArg::Source::Attribute;
      CA.AttrId = Id;
      CA.Broadcast = From != P.Type.Base;
      return true;
    }
    case ArgValue::Kind::NodeRef: {
      unsigned Index;
      if (!resolveNodeRef("node '" + N.Id + "': argument '" + P.Name + "'", A, Index))
        return false;
      const FunctionSignature *S = signatureOf(Index);
      if (!S)
        return false; // already reported as an unknown function
      if (!isAssignable(S->Return, P.Type))
        return mismatch(N, P, A);
      CA.Src = CompiledArg::Source::Node;
      CA.NodeIndex = Index;
      CA.Broadcast = S->Return != P.Type.Base;
      return true;
    }
    }
    return false;
  }

  /// color: float3-compatible (float broadcast, float4 .xyz); the others: float.
  bool resolveBsdfInput(const std::string &MatName, const Bsdf &B, const std::string &Name,
                        const ArgValue &A, CompiledMaterial &M, CompiledBsdfInput &In) {
    In.Name = Name;
    bool IsColor = bsdfInputIsVector(Name);
    bool IsNormal = Name == "normal";
    std::string What = "material '" + MatName + "': " + B.Type + " input '" + Name + "'";
    std::string Expects = IsNormal  ? "a normal (float3 or float4)"
                          : IsColor ? "a color (float3, float4 or float)"
                                    : "float";
    if (IsNormal && A.K != ArgValue::Kind::NodeRef) {
      error(A.Loc,
            What + " expects a node computing a normal ({\"node\": id}), got " +
                numberList(A.Numbers),
            A.JsonPath);
      return false;
    }
    if (A.K == ArgValue::Kind::NodeRef) {
      unsigned Index;
      if (!resolveNodeRef(What, A, Index))
        return false;
      const FunctionSignature *S = signatureOf(Index);
      if (!S)
        return false;
      bool Ok = IsNormal  ? S->Return == BaseType::Float3 || S->Return == BaseType::Float4
                : IsColor ? S->Return != BaseType::Float2
                          : S->Return == BaseType::Float;
      if (!Ok) {
        error(A.Loc,
              What + " expects " + Expects + ", got node '" + A.Ref + "' of type " +
                  spelling(S->Return),
              A.JsonPath);
        return false;
      }
      In.IsOutput = true;
      In.Output = outputFor(M, Index, S->Return);
      return true;
    }
    size_t Count = A.Numbers.size();
    bool Ok = IsColor ? (Count == 1 || Count == 3 || Count == 4) : Count == 1;
    if (!Ok) {
      error(A.Loc, What + " expects " + Expects + ", got " + numberList(A.Numbers), A.JsonPath);
      return false;
    }
    In.Constant = A.Numbers;
    if (IsColor)
      In.Constant.resize(3, A.Numbers.front()); // a number broadcasts; float4 keeps .xyz
    return true;
  }

  unsigned outputFor(CompiledMaterial &M, unsigned Node, BaseType T) {
    for (size_t I = 0; I < M.Outputs.size(); ++I)
      if (M.Outputs[I].Node == Node)
        return static_cast<unsigned>(I);
    MaterialOutput O;
    O.Node = Node;
    O.Type = T;
    M.Outputs.push_back(O);
    return static_cast<unsigned>(M.Outputs.size() - 1);
  }

  void resolveBsdf(const std::string &MatName, const Bsdf &B, CompiledMaterial &M,
                   CompiledBsdf &Out) {
    Out.Type = B.Type;
    // Canonical input order (bsdfInputs), so that outputs come in a stable order.
    for (const std::string &Name : bsdfInputs(B.Type)) {
      for (const auto &[InName, A] : B.Inputs) {
        if (InName != Name)
          continue;
        CompiledBsdfInput In;
        if (resolveBsdfInput(MatName, B, Name, A, M, In))
          Out.Inputs.push_back(std::move(In));
      }
      for (const auto &[ChildName, Child] : B.Children) {
        if (ChildName != Name)
          continue;
        CompiledBsdf C;
        resolveBsdf(MatName, Child, M, C);
        Out.Children.emplace_back(ChildName, std::move(C));
      }
    }
  }

  void resolveMaterial(const Material &Mat) {
    CompiledMaterial M;
    M.Name = Mat.Name;
    M.Index = static_cast<unsigned>(CG.Materials.size());
    resolveBsdf(Mat.Name, Mat.Root, M, M.Bsdf);
    CG.Materials.push_back(std::move(M));
  }

  /// Iterative three-colour DFS in file order; reports the first cycle found, in edge order.
  bool checkCycles() {
    enum Colour { White, Grey, Black };
    std::vector<Colour> State(CG.Nodes.size(), White);
    for (unsigned Start = 0; Start < CG.Nodes.size(); ++Start) {
      if (State[Start] != White)
        continue;
      std::vector<std::pair<unsigned, size_t>> Stack = {{Start, 0}};
      State[Start] = Grey;
      while (!Stack.empty()) {
        auto &[Node, Next] = Stack.back();
        const std::vector<CompiledArg> &Args = CG.Nodes[Node].Args;
        if (Next == Args.size()) {
          State[Node] = Black;
          Stack.pop_back();
          continue;
        }
        const CompiledArg &A = Args[Next++];
        if (A.Src != CompiledArg::Source::Node)
          continue;
        if (State[A.NodeIndex] == White) {
          State[A.NodeIndex] = Grey;
          Stack.push_back({A.NodeIndex, 0});
        } else if (State[A.NodeIndex] == Grey) {
          reportCycle(Stack, A.NodeIndex);
          return false;
        }
      }
    }
    return true;
  }

  void reportCycle(const std::vector<std::pair<unsigned, size_t>> &Stack, unsigned Target) {
    size_t First = 0;
    while (Stack[First].first != Target)
      ++First;
    // A long cycle prints its first and last nodes only: the diagnostic stays one line.
    const size_t Length = Stack.size() - First, Ends = 8;
    std::string Path;
    for (size_t I = First; I < Stack.size(); ++I) {
      if (Length > 2 * Ends && I == First + Ends) {
        Path += "... (" + std::to_string(Length - 2 * Ends) + " more) -> ";
        I = Stack.size() - Ends - 1;
        continue;
      }
      Path += "'" + CG.Nodes[Stack[I].first].Id + "' -> ";
    }
    Path += "'" + CG.Nodes[Target].Id + "'";
    const Node &N = G.Nodes[Target];
    error(N.IdLoc.Line ? N.IdLoc : N.Loc, "cycle in the node graph: " + Path,
          N.JsonPath);
  }

  void warnUnused() {
    std::vector<bool> Reached(CG.Nodes.size(), false);
    std::vector<unsigned> Work;
    for (const CompiledMaterial &M : CG.Materials)
      for (const MaterialOutput &O : M.Outputs)
        Work.push_back(O.Node);
    while (!Work.empty()) {
      unsigned N = Work.back();
      Work.pop_back();
      if (Reached[N])
        continue;
      Reached[N] = true;
      for (const CompiledArg &A : CG.Nodes[N].Args)
        if (A.Src == CompiledArg::Source::Node)
          Work.push_back(A.NodeIndex);
    }
    for (size_t I = 0; I < CG.Nodes.size(); ++I)
      if (!Reached[I])
        Diags.warning(CG.Nodes[I].Loc,
                      withPath("node '" + CG.Nodes[I].Id + "' is not used by any material",
                               G.Nodes[I].JsonPath));
  }

  const Graph &G;
  const SignatureMap &Sigs;
  const CompileOptions &Opts;
  DiagnosticSink &Diags;
  CompiledGraph CG;
  std::map<std::string, unsigned> IndexOf;
};

} // namespace

std::optional<CompiledGraph> resolveGraph(const Graph &G, const SignatureMap &Sigs,
                                          const CompileOptions &Opts, DiagnosticSink &Diags) {
  return Resolver(G, withBuiltinSignatures(Sigs), Opts, Diags).run(); // bump (Bump.h)
}

bool validateGraph(const Graph &G, const SignatureMap &Sigs, const CompileOptions &Opts,
                   DiagnosticSink &Diags) {
  return resolveGraph(G, Sigs, Opts, Diags).has_value();
}

} // namespace texcc::graph
