// inline: per material a straight-line function, constants baked in as literals, the material's
// nodes called in topological order into locals (the paper's "Cycles simulation"); the kernel
// texcc_proctex switches on the material. The host target reuses the material functions.
#include "Emit.h"

using namespace texcc::graph;

namespace texcc::codegen {

std::string materialFunctionName(const CompiledMaterial &M) {
  return "texcc_material_" + std::to_string(M.Index);
}

void emitStraightLineMaterial(std::ostringstream &OS, const CompiledGraph &CG,
                              const CompiledMaterial &M, Target T) {
  const bool Host = T == Target::Host;
  OS << "/* material " << M.Index << " '" << M.Name << "': " << describeOutputs(CG, M)
     << " */\n";
  if (Host)
    OS << "static void " << materialFunctionName(M)
       << "(const TexccCtx *texcc_ctx, float4 *out) {\n";
  else
    OS << "TEXCC_FN static inline void " << materialFunctionName(M)
       << "(const TexccCtx *texcc_ctx, __global const uint *fakeStack,\n"
       << "    __global float4 *out) {\n";
  ArgEmitter E;
  E.Tgt = T;
  E.BakeConstants = true;
  E.ChildExpr = [&CG](unsigned Child) { return nodeLocalName(CG.Nodes[Child], Child); };
  int Offset = -1;
  for (size_t J = 0; J < M.Program.size(); ++J) {
    const Instruction &I = M.Program[J];
    const CompiledNode &N = CG.Nodes[I.Node];
    const std::string Move = positionOffsetStatement(CG, N, Offset);
    if (!Move.empty())
      OS << "  " << Move << "\n";
    OS << "  " << guardAtInstruction(J) << "\n"
       << "  const " << spelling(N.Return) << " " << nodeLocalName(N, I.Node) << " = "
       << E.call(CG, I.Node) << ";\n";
  }
  for (size_t K = 0; K < M.Outputs.size(); ++K) {
    const MaterialOutput &O = M.Outputs[K];
    OS << "  out[" << K << "] = "
       << widenToFloat4(CG.Nodes[O.Node].Return, nodeLocalName(CG.Nodes[O.Node], O.Node), T)
       << ";\n";
  }
  OS << "}\n\n";
}

void emitInline(std::ostringstream &OS, const CompiledGraph &CG) {
  for (const CompiledMaterial &M : CG.Materials)
    if (!M.Outputs.empty())
      emitStraightLineMaterial(OS, CG, M, Target::OpenCL);
  OS << "__kernel void texcc_proctex(\n" << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, "");
  OS << "  __global float4 *out = outputs + gid * TEXCC_MAX_OUTPUTS;\n"
     << "  switch (mat) {\n";
  for (const CompiledMaterial &M : CG.Materials)
    if (!M.Outputs.empty())
      OS << "  case " << M.Index << ":\n"
         << "    " << materialFunctionName(M) << "(texcc_ctx, fakeStack, out);\n"
         << "    break;\n";
  OS << "  default:\n"
     << "    break;\n"
     << "  }\n"
     << kernelEpilogue() << "}\n";
}

} // namespace texcc::codegen
