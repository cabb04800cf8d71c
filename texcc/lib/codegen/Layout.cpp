// layout.json: the graph library's part of the manifest (graph::layoutManifest) plus what the
// backend decides (Backend.h): the kernel entry points and launch plan, the scratch size per hit
// and its capabilities; written by the kernel library (writeManifest). No mode is named here.
#include "Emit.h"
#include "texcc/Codegen/Backend.h"

using namespace texcc::graph;

namespace texcc::codegen {

std::string generateLayout(const CompiledGraph &CG, const CodegenOptions &Opts) {
  kernel::Manifest M = layoutManifest(CG);
  for (kernel::FunctionLayout &F : M.Functions) {
    auto Docs = Opts.ParamDocs.find(F.Name);
    if (Docs != Opts.ParamDocs.end() && Docs->second.size() == F.Params.size())
      for (size_t I = 0; I < F.Params.size(); ++I)
        F.Params[I].Doc = Docs->second[I];
  }
  M.Mode = modeName(Opts.EvalMode);
  M.Target = targetName(Opts.Tgt);
  M.Graph = Opts.GraphPath;
  M.CompileOptions = Opts.CompileOptions;
  const Backend &B = backendFor(Opts);
  M.Kernel = B.entries(CG, Opts);
  M.ScratchFloat4PerHit = B.scratchFloat4PerHit(CG);
  // Spilling is an interpreter matter: other kernels have no value stack (shape mode keeps it
  // for its interp fallback).
  if (!B.writesInterpreter())
    M.Spill = false;
  M.Caps = B.capabilities(CG, Opts);
  M.Caps.MaxOutputs = M.MaxOutputs;
  M.Caps.OutputsEntry = M.Kernel.Entry;
  return kernel::writeManifest(M);
}

} // namespace texcc::codegen
