// layout.json: the graph library's part (graph::layoutJson) plus what code generation decides:
// the mode, the target, the kernel entry points and launch plan, the scratch size per hit.
#include "Emit.h"

#include <nlohmann/json.hpp>

using namespace texcc::graph;
using Json = nlohmann::ordered_json;

namespace texcc::codegen {

static Json kernelJson(const CompiledGraph &CG, const CodegenOptions &Opts) {
  Json K = Json::object();
  K["source"] = kernelFileName(Opts.Tgt);
  if (Opts.Tgt == Target::Host) {
    K["entry"] = HostEntry;
    return K;
  }
  if (Opts.EvalMode == Mode::Shape) {
    K["entry"] = KernelEntry;
    K["interpFallback"] = InterpFallbackFile;
    Json Shapes = Json::array();
    std::vector<MaterialShape> Groups = groupShapes(CG);
    for (size_t I = 0; I < Groups.size(); ++I)
      Shapes.push_back(Json{{"id", I}, {"materials", Groups[I].Materials}});
    K["shapes"] = std::move(Shapes);
    K["shapeHash"] = shapeHash(CG);
    if (!hoistingFunctions(CG).empty())
      K["uniforms"] = UniformsEntry;
    return K;
  }
  if (Opts.EvalMode != Mode::Wavefront) {
    K["entry"] = KernelEntry;
    if (Opts.EvalMode == Mode::Interp && Opts.InterpHoists && !CG.Nodes.empty() &&
        !interpHoistingFunctions(CG).empty())
      K["uniforms"] = UniformsEntry;
    return K;
  }
  // Wavefront: every node kernel in launch order, then the outputs kernel ("entry").
  K["entry"] = WavefrontOutputsEntry;
  Json Launches = Json::array();
  for (unsigned N : CG.WavefrontOrder)
    Launches.push_back(Json{{"kernel", wavefrontKernelName(N)}, {"node", N}});
  K["launches"] = std::move(Launches);
  return K;
}

static unsigned scratchFloat4PerHit(const CompiledGraph &CG, const CodegenOptions &Opts) {
  if (Opts.Tgt == Target::Host)
    return 0;
  if (Opts.EvalMode == Mode::Wavefront)
    return static_cast<unsigned>(CG.Nodes.size());
  // Shape mode: for its interp fallback (the shape kernel itself needs no scratch).
  if ((Opts.EvalMode == Mode::Interp || Opts.EvalMode == Mode::Shape) && CG.Spill)
    return CG.StackSlots;
  return 0;
}

std::string generateLayout(const CompiledGraph &CG, const CodegenOptions &Opts) {
  Json Graph = Json::parse(layoutJson(CG));
  Json L = Json::object();
  L["texcc"] = Graph.contains("texcc") ? Graph["texcc"] : Json(1);
  L["mode"] = modeName(Opts.EvalMode);
  L["target"] = targetName(Opts.Tgt);
  L["graph"] = Opts.GraphPath;
  L["compileOptions"] = Opts.CompileOptions;
  L["kernel"] = kernelJson(CG, Opts);
  L["scratchFloat4PerHit"] = scratchFloat4PerHit(CG, Opts);
  for (auto It = Graph.begin(); It != Graph.end(); ++It)
    if (!L.contains(It.key()))
      L[It.key()] = It.value();
  // Spilling is an interpreter matter: other modes have no value stack (shape mode keeps it for
  // its interp fallback).
  const bool Interprets = Opts.EvalMode == Mode::Interp || Opts.EvalMode == Mode::Shape;
  if (!Interprets || Opts.Tgt == Target::Host)
    L["spill"] = false;
  return L.dump(2) + "\n";
}

} // namespace texcc::codegen
