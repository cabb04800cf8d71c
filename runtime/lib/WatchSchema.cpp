// The edit schema of texrender --watch --control (WatchSession.h, docs/live.md "Control
// channel"): what a front end may edit, from the live editor's typed graph and the kernel's
// manifest, sent in the 'ready' and 'reload' events so that the browser preview builds its
// controls from texrender's own graph and owns no schema of its own.
#include "WatchSession.h"

#include <algorithm>
#include <map>
#include <vector>

namespace texrender {
namespace watch {

namespace {

/// A parameter's table row as the manifest carries it (texcc read it from the source).
void addDoc(ordered_json &Input, const texcc::kernel::ParamDoc &D) {
  if (!D.Default.empty())
    Input["default"] = D.Default;
  if (!D.DefaultText.empty())
    Input["defaultText"] = D.DefaultText;
  if (!D.RangeText.empty())
    Input["range"] = D.RangeText;
  if (D.Min)
    Input["min"] = *D.Min;
  if (D.Max)
    Input["max"] = *D.Max;
  if (!D.Text.empty())
    Input["doc"] = D.Text;
}

/// What feeds an argument in the graph rendered now: {"node": id}, {"attr": name},
/// {"image": name} or {"value": v} (a baked argument's value too).
void addSource(ordered_json &Input, const texcc::graph::ArgValue &Arg) {
  using Kind = texcc::graph::ArgValue::Kind;
  switch (Arg.K) {
  case Kind::NodeRef:
    Input["node"] = Arg.Ref;
    return;
  case Kind::AttrRef:
    Input["attr"] = Arg.Ref;
    return;
  case Kind::ImageRef:
    Input["image"] = Arg.Ref;
    return;
  default:
    texcc::graph::ArgValue Value = Arg;
    Value.Bake = false;
    Input["value"] = texcc::graph::argumentJson(Value);
  }
}

/// The node ids a BSDF tree's inputs read, at any depth.
void bsdfNodes(const texcc::graph::Bsdf &B, std::vector<std::string> &Ids) {
  for (const auto &[Name, V] : B.Inputs)
    if (V.K == texcc::graph::ArgValue::Kind::NodeRef)
      Ids.push_back(V.Ref);
  for (const auto &[Name, Child] : B.Children)
    bsdfNodes(Child, Ids);
}

/// The ids of the nodes each material uses (sorted).
ordered_json materialNodes(const texcc::graph::Graph &G) {
  ordered_json Out = ordered_json::object();
  for (const texcc::graph::Material &M : G.Materials) {
    std::vector<std::string> Ids;
    bsdfNodes(M.Root, Ids);
    std::sort(Ids.begin(), Ids.end());
    Ids.erase(std::unique(Ids.begin(), Ids.end()), Ids.end());
    Out[M.Name] = Ids;
  }
  return Out;
}

/// One input's entry: its name, type, what feeds it in N, its parameter table row.
ordered_json inputEntry(const texcc::kernel::ParamLayout &P, const texcc::graph::Node &N) {
  ordered_json Input{{"name", P.Name}, {"type", P.Type}};
  for (const auto &[Name, V] : N.Args)
    if (Name == P.Name)
      addSource(Input, V);
  addDoc(Input, P.Doc);
  return Input;
}

const texcc::kernel::FunctionLayout *functionOf(const Layout &Lay, const std::string &Name) {
  for (const texcc::kernel::FunctionLayout &F : Lay.Manifest.Functions)
    if (F.Name == Name)
      return &F;
  return nullptr;
}

} // namespace

ordered_json inputSchema(const Layout &Lay, const texcc::graph::Graph &G, const std::string &Node,
                         const std::string &Arg) {
  const texcc::graph::Node *N = G.findNode(Node);
  const texcc::kernel::FunctionLayout *F = N ? functionOf(Lay, N->Fn) : nullptr;
  if (F)
    for (const texcc::kernel::ParamLayout &P : F->Params)
      if (P.Name == Arg)
        return inputEntry(P, *N);
  return nullptr;
}

ordered_json editSchema(const Layout &Lay, const texcc::graph::Graph &G) {
  std::map<std::string, const texcc::kernel::FunctionLayout *> Functions;
  for (const texcc::kernel::FunctionLayout &F : Lay.Manifest.Functions)
    Functions.emplace(F.Name, &F);
  ordered_json Nodes = ordered_json::array();
  for (const texcc::graph::Node &N : G.Nodes) {
    ordered_json Node{{"id", N.Id}, {"fn", N.Fn}};
    auto F = Functions.find(N.Fn);
    ordered_json Inputs = ordered_json::array();
    if (F != Functions.end()) {
      Node["file"] = F->second->File;
      Node["return"] = F->second->Return;
      for (const texcc::kernel::ParamLayout &P : F->second->Params)
        Inputs.push_back(inputEntry(P, N));
    }
    Node["inputs"] = std::move(Inputs);
    Nodes.push_back(std::move(Node));
  }
  return {{"nodes", std::move(Nodes)}, {"materials", materialNodes(G)}};
}

} // namespace watch
} // namespace texrender
