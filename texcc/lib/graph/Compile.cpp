// compileGraph(): validation, then the passes in order, then the encoding.

#include "texcc/Graph/Passes.h"

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

std::optional<CompiledGraph> compileGraph(const Graph &G, const SignatureMap &Sigs,
                                          const CompileOptions &Opts, DiagnosticSink &Diags) {
  std::optional<CompiledGraph> CG = resolveGraph(G, Sigs, Opts, Diags);
  if (!CG)
    return std::nullopt;
  removeUnreachableNodes(*CG, Opts.Log);
  mergeIdenticalNodes(*CG, Opts.Log);
  assignFunctionIds(*CG, Sigs, Opts, Opts.Log);
  orderPrograms(*CG, Opts.Log);
  allocateStackSlots(*CG, Opts.StackLimit, Opts.Log, Opts.LocalStackLimit);
  computeWavefrontOrder(*CG, Opts.Log);
  layoutArguments(*CG, Opts.Log);
  selectSuperinstructions(*CG, Opts, Opts.Log);
  selectQuickened(*CG, Opts, Opts.Log);
  encodeArgsBin(*CG);
  return CG;
}

} // namespace texcc::graph
