// --target=host: C++ over the GLM prelude (HostPrelude.hpp). Whatever the mode, the host code is
// the straight-line form (one function per material, constants and arrays as literals), so that
// it is independent of args.bin and of the device interpreter: it is the oracle the equivalence
// tests compare every mode with, and what one steps through in a debugger.
#include "Emit.h"

using namespace texcc::graph;

namespace texcc::codegen {

static void emitHostArrays(std::ostringstream &OS, const CompiledGraph &CG) {
  for (unsigned NodeIndex = 0; NodeIndex < CG.Nodes.size(); ++NodeIndex) {
    const CompiledNode &N = CG.Nodes[NodeIndex];
    for (const CompiledArg &A : N.Args) {
      if (!A.Type.IsGlobalArray)
        continue;
      std::string Elem = spelling(A.Type.Base);
      if (A.ArrayCount == 0) {
        OS << "static const " << Elem << " *const " << hostArrayName(NodeIndex, A)
           << " = nullptr;\n";
        continue;
      }
      unsigned C = componentCount(A.Type.Base);
      OS << "/* node " << NodeIndex << " '" << N.Id << "', argument '" << A.Name << "' */\n"
         << "static const " << Elem << " " << hostArrayName(NodeIndex, A) << "[" << A.ArrayCount
         << "] = {\n";
      for (unsigned I = 0; I < A.ArrayCount; ++I)
        OS << "    " << constantLiteral(A.Type.Base, A.Values.data() + I * C, Target::Host)
           << ",\n";
      OS << "};\n";
    }
  }
  OS << "\n";
}

void emitHost(std::ostringstream &OS, const CompiledGraph &CG) {
  emitHostArrays(OS, CG);
  for (const CompiledMaterial &M : CG.Materials)
    if (!M.Outputs.empty())
      emitStraightLineMaterial(OS, CG, M, Target::Host);
  OS << "/* Evaluates material `material` at one hit: writes its outputs (4 floats each, a float\n"
        " * in [0], ...) to outputs and returns how many; -1 for a material index out of range.\n"
        " * texels and images as the kernel's arguments 5 and 6 (docs/abi.md). */\n"
     << "extern \"C\" int " << HostEntry << "(int material, const TexccHitAttrs *hit,\n"
     << "    const TexccSettings *settings, const cl_float4 *texels, const TexccImageInfo *images,\n"
     << "    float *outputs) {\n"
        "  if (material < 0 || material >= TEXCC_NUM_MATERIALS)\n"
        "    return -1;\n"
        "  TexccCtx ctx;\n"
        "  ctx.hit = *hit;\n"
        "  ctx.settings = settings;\n"
        "  ctx.texels = texels;\n"
        "  ctx.images = images;\n"
        "  TexccGuard guard = {TEXCC_LOOP_BUDGET, 0u, 0, material, nullptr, 0, 0u};\n"
        "  ctx.guard = &guard;\n"
        "  float4 out[TEXCC_MAX_OUTPUTS];\n"
        "  int n = 0;\n"
        "  switch (material) {\n";
  for (const CompiledMaterial &M : CG.Materials)
    if (!M.Outputs.empty())
      OS << "  case " << M.Index << ":\n"
         << "    " << materialFunctionName(M) << "(&ctx, out);\n"
         << "    n = " << M.Outputs.size() << ";\n"
         << "    break;\n";
  OS << "  default:\n"
        "    break;\n"
        "  }\n"
        "  for (int k = 0; k < n; ++k)\n"
        "    for (int c = 0; c < 4; ++c)\n"
        "      outputs[4 * k + c] = out[k][c];\n"
        "  return n;\n"
        "}\n";
}

} // namespace texcc::codegen
