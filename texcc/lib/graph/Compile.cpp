// compileGraph(): validation, then the passes in order, then the encoding.

#include "texcc/Graph/Bump.h"
#include "texcc/Graph/Passes.h"
#include "texcc/OutOfMemory.h"

namespace texcc::graph {

int CompiledGraph::findNode(const std::string &Id) const {
  for (size_t I = 0; I < Nodes.size(); ++I) {
    if (Nodes[I].Id == Id)
      return static_cast<int>(I);
    for (const std::string &M : Nodes[I].MergedIds)
      if (M == Id)
        return static_cast<int>(I);
  }
  return -1;
}

std::set<std::string> CompiledGraph::liveFunctions() const {
  std::set<std::string> Live;
  for (const CompiledNode &N : Nodes)
    Live.insert(N.Fn);
  return Live;
}

namespace {

/// compileGraph()'s steps after the validation; All: the signatures with the built-ins.
CompiledGraph runPasses(CompiledGraph CG, const SignatureMap &All, const CompileOptions &Opts) {
  whileAllocating("optimizing the node graph", [&] {
    removeUnreachableNodes(CG, Opts.Log);
    mergeIdenticalNodes(CG, Opts.Log);
    assignFunctionIds(CG, All, Opts, Opts.Log);
  });
  whileAllocating("encoding the material programs", [&] {
    orderPrograms(CG, Opts.Log);
    allocateStackSlots(CG, Opts.StackLimit, Opts.Log);
    computeWavefrontOrder(CG, Opts.Log);
  });
  whileAllocating("laying out the arguments", [&] { layoutArguments(CG, Opts.Log); });
  whileAllocating("encoding args.bin", [&] {
    applyQuickened(CG, Opts.Quickened, Opts.Log); // the kernel's table (live edits)
    encodeArgsBin(CG);
  });
  return CG;
}

} // namespace

std::optional<CompiledGraph> compileGraph(const Graph &G, const SignatureMap &Sigs,
                                          const CompileOptions &Opts, DiagnosticSink &Diags) {
  // Each step names what it allocates, for "out of memory while ..." (texcc/OutOfMemory.h).
  const SignatureMap All = withBuiltinSignatures(Sigs); // bump and its helpers (Bump.h)
  std::optional<CompiledGraph> CG = whileAllocating(
      "building the node and material tables", [&] { return resolveWithBump(G, All, Opts, Diags); });
  if (!CG)
    return std::nullopt;
  return runPasses(std::move(*CG), All, Opts);
}

CompiledGraph compileResolved(CompiledGraph Resolved, const SignatureMap &Sigs,
                              const CompileOptions &Opts) {
  return runPasses(std::move(Resolved), withBuiltinSignatures(Sigs), Opts);
}

} // namespace texcc::graph
