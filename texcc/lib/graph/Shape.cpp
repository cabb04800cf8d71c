// Material shapes (shape mode) and baked arguments (--bake NODE.ARG). A shape is the part of a
// program that code depends on when every unbaked constant is read from args.bin: functions,
// wiring, broadcasts, outputs and the baked values.

#include "texcc/Graph/Compile.h"

#include "Json.h"

#include <cstring>
#include <unordered_map>

namespace texcc::graph {

bool markBaked(Graph &G, const std::string &NodeDotArg, std::string &Error) {
  size_t Dot = NodeDotArg.rfind('.');
  if (Dot == std::string::npos || Dot == 0 || Dot + 1 == NodeDotArg.size()) {
    Error = "--bake '" + NodeDotArg + "': expected NODE.ARG";
    return false;
  }
  const std::string Id = NodeDotArg.substr(0, Dot), Arg = NodeDotArg.substr(Dot + 1);
  Node *N = G.findNode(Id);
  if (!N) {
    std::vector<std::string> Ids;
    for (const Node &Other : G.Nodes)
      Ids.push_back(Other.Id);
    std::string Near = json::closestMatch(Id, Ids);
    Error = "--bake '" + NodeDotArg + "': unknown node '" + Id + "'" +
            (Near.empty() ? "" : "; did you mean '" + Near + "'?");
    return false;
  }
  std::vector<std::string> Names;
  for (auto &[Name, Value] : N->Args) {
    Names.push_back(Name);
    if (Name != Arg)
      continue;
    if (Value.K != ArgValue::Kind::Number && Value.K != ArgValue::Kind::Vector) {
      Error = "--bake '" + NodeDotArg + "': argument '" + Arg + "' of node '" + Id +
              "' is not a number or a vector; only constants can be baked";
      return false;
    }
    Value.Bake = true;
    return true;
  }
  std::string Near = json::closestMatch(Arg, Names);
  Error = "--bake '" + NodeDotArg + "': node '" + Id + "' has no argument '" + Arg + "'" +
          (Near.empty() ? "" : "; did you mean '" + Near + "'?");
  return false;
}

/// A baked value in the key: the float32 bits of every component (what the literal holds).
static std::string bakedValueKey(const CompiledArg &A) {
  std::string K = "=";
  for (double V : A.Values) {
    float F = static_cast<float>(V);
    uint32_t Bits;
    std::memcpy(&Bits, &F, sizeof Bits);
    K += std::to_string(Bits) + " ";
  }
  return K;
}

std::string shapeKey(const CompiledGraph &CG, const CompiledMaterial &M) {
  // Nodes are named by their position in the program, so that materials over different nodes
  // of equal structure get equal keys.
  std::unordered_map<unsigned, size_t> Position;
  std::string K;
  for (size_t J = 0; J < M.Program.size(); ++J) {
    const CompiledNode &N = CG.Nodes[M.Program[J].Node];
    Position[M.Program[J].Node] = J;
    K += N.Fn + (N.PositionOffset ? "@" + std::to_string(N.PositionOffset) : "") + "(";
    for (const CompiledArg &A : N.Args) {
      switch (A.Src) {
      case CompiledArg::Source::Constant:
        K += A.Bake ? "k" + bakedValueKey(A) : "c";
        break;
      case CompiledArg::Source::Attribute:
        K += "a" + std::to_string(A.AttrId);
        break;
      case CompiledArg::Source::Node:
        K += "n" + std::to_string(Position.at(A.NodeIndex));
        break;
      }
      K += A.Broadcast ? "b," : ",";
    }
    K += ");";
  }
  K += "->";
  for (const MaterialOutput &O : M.Outputs)
    K += std::to_string(Position.at(O.Node)) + ",";
  return K;
}

std::vector<MaterialShape> groupShapes(const CompiledGraph &CG) {
  std::vector<MaterialShape> Shapes;
  std::unordered_map<std::string, size_t> IndexOf;
  for (const CompiledMaterial &M : CG.Materials) {
    if (M.Outputs.empty())
      continue;
    std::string Key = shapeKey(CG, M);
    auto [It, Inserted] = IndexOf.emplace(Key, Shapes.size());
    if (Inserted)
      Shapes.push_back({std::move(Key), {}});
    Shapes[It->second].Materials.push_back(M.Index);
  }
  return Shapes;
}

std::string shapeHash(const CompiledGraph &CG) {
  uint64_t H = 1469598103934665603ull;
  auto Mix = [&H](const std::string &S) {
    for (unsigned char C : S)
      H = (H ^ C) * 1099511628211ull;
    H = (H ^ 0xFFu) * 1099511628211ull; // a separator no key contains
  };
  for (const CompiledMaterial &M : CG.Materials)
    Mix(M.Outputs.empty() ? std::string() : shapeKey(CG, M));
  static const char Hex[] = "0123456789abcdef";
  std::string S(16, '0');
  for (int I = 15; I >= 0; --I, H >>= 4)
    S[I] = Hex[H & 0xFu];
  return S;
}

} // namespace texcc::graph
