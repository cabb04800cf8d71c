// The edit schema of texrender --watch --control (WatchSession.h, docs/live.md "Control
// channel"): what a front end may edit, sent in the 'ready' and 'reload' events so that the
// browser preview builds its controls from texrender's own graph and manifest and owns no
// schema of its own.
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
void addSource(ordered_json &Input, const json &Arg) {
  if (Arg.is_object()) {
    for (const char *Key : {"node", "attr", "image"})
      if (Arg.contains(Key)) {
        Input[Key] = Arg[Key];
        return;
      }
    if (Arg.contains("value")) {
      Input["value"] = Arg["value"];
      return;
    }
  }
  Input["value"] = Arg;
}

/// The ids of the nodes each material uses (its {"node": id} inputs, at any depth of its tree).
ordered_json materialNodes(const json &Graph) {
  ordered_json Out = ordered_json::object();
  if (!Graph.contains("materials") || !Graph["materials"].is_object())
    return Out;
  for (const auto &[Name, Tree] : Graph["materials"].items()) {
    std::vector<std::string> Ids;
    std::vector<const json *> Todo{&Tree};
    while (!Todo.empty()) {
      const json *J = Todo.back();
      Todo.pop_back();
      if (J->is_object() && J->contains("node") && (*J)["node"].is_string())
        Ids.push_back((*J)["node"].get<std::string>());
      if (J->is_structured())
        for (const json &Child : *J)
          Todo.push_back(&Child);
    }
    std::sort(Ids.begin(), Ids.end());
    Ids.erase(std::unique(Ids.begin(), Ids.end()), Ids.end());
    Out[Name] = Ids;
  }
  return Out;
}

} // namespace

ordered_json editSchema(const Layout &Lay, const json &Graph) {
  std::map<std::string, const texcc::kernel::FunctionLayout *> Functions;
  for (const texcc::kernel::FunctionLayout &F : Lay.Manifest.Functions)
    Functions.emplace(F.Name, &F);
  ordered_json Nodes = ordered_json::array();
  if (Graph.contains("nodes") && Graph["nodes"].is_array())
    for (const json &N : Graph["nodes"]) {
      if (!N.is_object() || !N.contains("id") || !N.contains("fn"))
        continue;
      const std::string Fn = N["fn"].is_string() ? N["fn"].get<std::string>() : "";
      ordered_json Node{{"id", N["id"]}, {"fn", Fn}};
      auto F = Functions.find(Fn);
      ordered_json Inputs = ordered_json::array();
      if (F != Functions.end()) {
        Node["file"] = F->second->File;
        Node["return"] = F->second->Return;
        const json Args = N.contains("args") && N["args"].is_object() ? N["args"] : json::object();
        for (const texcc::kernel::ParamLayout &P : F->second->Params) {
          ordered_json Input{{"name", P.Name}, {"type", P.Type}};
          if (Args.contains(P.Name))
            addSource(Input, Args[P.Name]);
          addDoc(Input, P.Doc);
          Inputs.push_back(std::move(Input));
        }
      }
      Node["inputs"] = std::move(Inputs);
      Nodes.push_back(std::move(Node));
    }
  return {{"nodes", std::move(Nodes)}, {"materials", materialNodes(Graph)}};
}

} // namespace watch
} // namespace texrender
