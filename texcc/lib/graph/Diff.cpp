// Edits as data (Diff.h): the edit type, its text, its application to the model, the edits
// between two graphs, and the graph.json writer they share with texrender's regenerations.

#include "texcc/Graph/Diff.h"

#include <algorithm>
#include <unordered_set>

namespace texcc::graph {

namespace {

using json = nlohmann::ordered_json;

const ArgValue *findArg(const std::vector<std::pair<std::string, ArgValue>> &Args,
                        const std::string &Name) {
  for (const auto &[Key, V] : Args)
    if (Key == Name)
      return &V;
  return nullptr;
}

/// Same names with the same values, in any order.
bool sameArgs(const std::vector<std::pair<std::string, ArgValue>> &A,
              const std::vector<std::pair<std::string, ArgValue>> &B) {
  if (A.size() != B.size())
    return false;
  for (const auto &[Name, V] : A) {
    const ArgValue *Other = findArg(B, Name);
    if (!Other || !sameValue(V, *Other))
      return false;
  }
  return true;
}

bool sameBsdf(const Bsdf &A, const Bsdf &B) {
  if (A.Type != B.Type || !sameArgs(A.Inputs, B.Inputs) || A.Children.size() != B.Children.size())
    return false;
  for (const auto &[Name, Child] : A.Children) {
    auto It = std::find_if(B.Children.begin(), B.Children.end(),
                           [&](const auto &C) { return C.first == Name; });
    if (It == B.Children.end() || !sameBsdf(Child, It->second))
      return false;
  }
  return true;
}

/// Why Old and New differ other than in node arguments ("" when they do not).
std::string outsideNodes(const Graph &Old, const Graph &New) {
  if (Old.Sources != New.Sources)
    return "the sources changed";
  if (Old.Images != New.Images || Old.ImageColorSpaces != New.ImageColorSpaces)
    return "the images changed";
  if (Old.Materials.size() != New.Materials.size())
    return "the materials changed";
  for (size_t I = 0; I < Old.Materials.size(); ++I) {
    const Material &A = Old.Materials[I], &B = New.Materials[I];
    if (A.Name != B.Name)
      return "the materials changed";
    if (!sameBsdf(A.Root, B.Root))
      return "material '" + B.Name + "' changed";
  }
  return "";
}

/// Why the node lists differ other than in arguments ("" when they do not).
std::string nodeListChange(const Graph &Old, const Graph &New) {
  // Sets of ids: a graph may have thousands of nodes, and findNode walks them.
  auto ids = [](const Graph &G) {
    std::unordered_set<std::string> Ids;
    for (const Node &N : G.Nodes)
      Ids.insert(N.Id);
    return Ids;
  };
  const std::unordered_set<std::string> OldIds = ids(Old), NewIds = ids(New);
  for (const Node &N : New.Nodes)
    if (!OldIds.count(N.Id))
      return "node '" + N.Id + "' added";
  for (const Node &N : Old.Nodes)
    if (!NewIds.count(N.Id))
      return "node '" + N.Id + "' removed";
  if (Old.Nodes.size() != New.Nodes.size())
    return "the number of nodes changed";
  for (size_t I = 0; I < New.Nodes.size(); ++I) {
    const Node &A = Old.Nodes[I], &B = New.Nodes[I];
    if (A.Id != B.Id)
      return "the nodes' order changed ('" + B.Id + "' where '" + A.Id + "' was)";
    if (A.Fn != B.Fn)
      return "node '" + B.Id + "' calls '" + B.Fn + "' instead of '" + A.Fn + "'";
  }
  return "";
}

} // namespace

bool isConstant(const ArgValue &A) {
  return A.K == ArgValue::Kind::Number || A.K == ArgValue::Kind::Vector ||
         A.K == ArgValue::Kind::Array;
}

bool sameValue(const ArgValue &A, const ArgValue &B) {
  // A reference is never baked: its bake mark (kept over a rewiring) means nothing.
  return A.K == B.K && A.Numbers == B.Numbers && A.Rows == B.Rows &&
         A.IsArrayOfRows == B.IsArrayOfRows && A.IsInteger == B.IsInteger &&
         (!isConstant(A) || A.Bake == B.Bake) && A.Ref == B.Ref;
}

Edit rewireEdit(std::string Node, std::string Arg, std::string Source) {
  Edit E;
  E.K = Edit::Kind::Rewire;
  E.Node = std::move(Node);
  E.Arg = std::move(Arg);
  E.Value.K = ArgValue::Kind::NodeRef;
  E.Value.Ref = std::move(Source);
  return E;
}

std::string editText(const Edit &E) {
  if (E.K == Edit::Kind::Rewire)
    return "rewire " + E.Node + "." + E.Arg + "=" + E.Value.Ref;
  return "set " + E.Node + "." + E.Arg + "=" + argumentJson(E.Value).dump();
}

bool applyEdit(Graph &G, const Edit &E, std::string &Why) {
  Node *N = G.findNode(E.Node);
  if (!N) {
    Why = "unknown node '" + E.Node + "'";
    return false;
  }
  auto Slot = std::find_if(N->Args.begin(), N->Args.end(),
                           [&](const auto &A) { return A.first == E.Arg; });
  ArgValue New = E.Value;
  if (Slot == N->Args.end()) {
    New.JsonPath = N->JsonPath + "/args/" + E.Arg;
    N->Args.emplace_back(E.Arg, std::move(New));
    return true;
  }
  // A baked constant is a literal of the shape code: a new value stays baked.
  if (E.K == Edit::Kind::Set)
    New.Bake |= Slot->second.Bake;
  New.KeyLoc = Slot->second.KeyLoc;
  New.JsonPath = Slot->second.JsonPath;
  Slot->second = std::move(New);
  return true;
}

std::optional<std::vector<Edit>> diff(const Graph &Old, const Graph &New, std::string &Why) {
  Why = outsideNodes(Old, New);
  if (Why.empty())
    Why = nodeListChange(Old, New);
  if (!Why.empty())
    return std::nullopt;
  std::vector<Edit> Edits;
  for (size_t I = 0; I < New.Nodes.size(); ++I) {
    const Node &A = Old.Nodes[I], &B = New.Nodes[I];
    for (const auto &[Name, Was] : A.Args)
      if (!findArg(B.Args, Name)) {
        Why = "argument '" + B.Id + "." + Name + "' removed";
        return std::nullopt;
      }
    for (const auto &[Name, Now] : B.Args) {
      const ArgValue *Was = findArg(A.Args, Name);
      if (Was && sameValue(*Was, Now))
        continue;
      if (Was && isConstant(*Was) && isConstant(Now) && Was->Bake != Now.Bake) {
        Why = "argument '" + B.Id + "." + Name + "' " + (Now.Bake ? "baked" : "no longer baked") +
              " (the shape code changes)";
        return std::nullopt;
      }
      Edit E;
      E.Node = B.Id;
      E.Arg = Name;
      E.Value = Now;
      Edits.push_back(std::move(E));
    }
  }
  return Edits;
}

bool sameGraph(const Graph &A, const Graph &B) {
  std::string Why;
  std::optional<std::vector<Edit>> D = diff(A, B, Why);
  return D && D->empty();
}

json argumentJson(const ArgValue &A) {
  using Kind = ArgValue::Kind;
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

namespace {

json bsdfJson(const Bsdf &B) {
  json J;
  J["bsdf"] = B.Type;
  for (const auto &[Name, V] : B.Inputs)
    J[Name] = argumentJson(V);
  for (const auto &[Name, Child] : B.Children)
    J[Name] = bsdfJson(Child);
  return J;
}

} // namespace

json graphJson(const Graph &G) {
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
  for (const Node &N : G.Nodes) {
    json Args = json::object();
    for (const auto &[Name, V] : N.Args)
      Args[Name] = argumentJson(V);
    Nodes.push_back(json{{"id", N.Id}, {"fn", N.Fn}, {"args", Args}});
  }
  J["nodes"] = Nodes;
  json Materials = json::object();
  for (const Material &M : G.Materials)
    Materials[M.Name] = bsdfJson(M.Root);
  J["materials"] = Materials;
  return J;
}

} // namespace texcc::graph
