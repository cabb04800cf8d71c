// wavefront: one kernel per live node, texcc_wf_<node>, launched over all hits in the order of
// layout.json kernel.launches (CompiledGraph::WavefrontOrder); node values live in the global
// SoA scratch (node n of hit i at n*numHits + i); texcc_wf_outputs copies the material outputs.
// Constants are read from the node's record in fakeStack, so a parameter edit is an upload.
#include "Emit.h"

using namespace texcc::graph;

namespace texcc::codegen {

static std::string scratchAt(unsigned Node) {
  return "scratch[" + std::to_string(Node) + "u * (uint)numHits + (uint)gid]";
}

/// For each node, the materials whose programs run it, ascending (each program lists a node
/// once); built in one pass over the programs, so the kernel's text is linear in their length
/// (a materials x nodes table was quadratic: 100,000 materials of one node each made 10^10).
static std::vector<std::vector<unsigned>> nodeUsers(const CompiledGraph &CG) {
  std::vector<std::vector<unsigned>> Users(CG.Nodes.size());
  for (const CompiledMaterial &M : CG.Materials)
    for (const Instruction &I : M.Program)
      if (Users[I.Node].empty() || Users[I.Node].back() != M.Index)
        Users[I.Node].push_back(M.Index);
  return Users;
}

/// texcc_wf_uses_<n>(mat): whether material mat's program runs node n (other materials' hits
/// skip the node's launch); "" (no test) when every material runs it.
static std::string emitUses(std::ostringstream &OS, const CompiledGraph &CG, unsigned NodeIndex,
                            const std::vector<unsigned> &Users) {
  if (Users.size() == CG.Materials.size())
    return "";
  const std::string Name = "texcc_wf_uses_" + std::to_string(NodeIndex);
  OS << "static inline bool " << Name << "(int mat) {\n"
     << "  switch (mat) {\n";
  for (unsigned M : Users)
    OS << "  case " << M << ": /* '" << CG.Materials[M].Name << "' */\n";
  if (!Users.empty())
    OS << "    return true;\n";
  OS << "  default:\n"
     << "    return false;\n"
     << "  }\n"
     << "}\n";
  return " || !" + Name + "(mat)";
}

static void emitNodeKernel(std::ostringstream &OS, const CompiledGraph &CG, unsigned NodeIndex,
                           const std::vector<unsigned> &Users) {
  const CompiledNode &N = CG.Nodes[NodeIndex];
  const FunctionSignature &Sig = CG.Signatures.at(N.Fn);
  const std::string Skip = emitUses(OS, CG, NodeIndex, Users);
  OS << "/* node " << NodeIndex << " '" << N.Id << "': " << signatureComment(Sig) << ", "
     << Sig.File << "; record at byte " << N.RecordOffset << " */\n"
     << "__kernel void " << wavefrontKernelName(NodeIndex) << "(\n"
     << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, Skip,
                     "TEXCC_AT_NODE | " + std::to_string(NodeIndex) + "u");
  int Offset = -1;
  const std::string Move = positionOffsetStatement(CG, N, Offset);
  if (!Move.empty())
    OS << "  " << Move << "\n";
  ArgEmitter E;
  E.Tgt = Target::OpenCL;
  E.ArgIndent = 10;
  E.BakeConstants = false;
  E.ChildExpr = [&CG](unsigned Child) {
    return scratchAt(Child) + narrowSwizzle(CG.Nodes[Child].Return);
  };
  OS << "  " << scratchAt(NodeIndex) << " =\n      "
     << widenToFloat4(N.Return, E.call(CG, NodeIndex), Target::OpenCL) << ";\n"
     << kernelEpilogue() << "}\n\n";
}

static void emitOutputsKernel(std::ostringstream &OS, const CompiledGraph &CG) {
  OS << "/* Copies every material's outputs from the node values into outputs. */\n"
     << "__kernel void " << WavefrontOutputsEntry << "(\n"
     << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, "");
  OS << "  __global float4 *out = outputs + gid * TEXCC_MAX_OUTPUTS;\n"
     << "  switch (mat) {\n";
  for (const CompiledMaterial &M : CG.Materials) {
    if (M.Outputs.empty())
      continue;
    OS << "  case " << M.Index << ":\n";
    for (size_t K = 0; K < M.Outputs.size(); ++K)
      OS << "    out[" << K << "] = " << scratchAt(M.Outputs[K].Node) << ";\n";
    OS << "    break;\n";
  }
  OS << "  default:\n"
     << "    break;\n"
     << "  }\n"
     << "}\n";
}

void emitWavefront(std::ostringstream &OS, const CompiledGraph &CG,
                   const std::string &OnlyFunction, bool OutputsOnly) {
  const std::vector<std::vector<unsigned>> Users = nodeUsers(CG);
  if (!OutputsOnly)
    for (unsigned NodeIndex : CG.WavefrontOrder)
      if (OnlyFunction.empty() || CG.Nodes[NodeIndex].Fn == OnlyFunction)
        emitNodeKernel(OS, CG, NodeIndex, Users[NodeIndex]);
  if (OnlyFunction.empty())
    emitOutputsKernel(OS, CG);
}

std::string quickProgramFile(const std::string &Fn) { return "proctex.quick.fn." + Fn + ".cl"; }

} // namespace texcc::codegen
