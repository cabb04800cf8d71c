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

static void emitUseTable(std::ostringstream &OS, const CompiledGraph &CG) {
  OS << "/* texcc_wf_uses[m][n]: whether material m's program runs node n (other materials' hits\n"
        " * skip the node's launch). */\n"
     << "#define TEXCC_WF_NODES " << CG.Nodes.size() << "\n"
     << "__constant uchar texcc_wf_uses[TEXCC_NUM_MATERIALS][TEXCC_WF_NODES] = {\n";
  for (const CompiledMaterial &M : CG.Materials) {
    std::vector<int> Uses(CG.Nodes.size(), 0);
    for (const Instruction &I : M.Program)
      Uses[I.Node] = 1;
    OS << "    {";
    for (size_t N = 0; N < Uses.size(); ++N)
      OS << (N ? ", " : "") << Uses[N];
    OS << "}, /* " << M.Index << " '" << M.Name << "' */\n";
  }
  OS << "};\n\n";
}

static void emitNodeKernel(std::ostringstream &OS, const CompiledGraph &CG, unsigned NodeIndex) {
  const CompiledNode &N = CG.Nodes[NodeIndex];
  const FunctionSignature &Sig = CG.Signatures.at(N.Fn);
  OS << "/* node " << NodeIndex << " '" << N.Id << "': " << signatureComment(Sig) << ", "
     << Sig.File << "; record at byte " << N.RecordOffset << " */\n"
     << "__kernel void " << wavefrontKernelName(NodeIndex) << "(\n"
     << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, " || !texcc_wf_uses[mat][" + std::to_string(NodeIndex) + "]",
                     "TEXCC_AT_NODE | " + std::to_string(NodeIndex) + "u");
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

void emitWavefront(std::ostringstream &OS, const CompiledGraph &CG) {
  if (!CG.Nodes.empty() && !CG.Materials.empty())
    emitUseTable(OS, CG);
  for (unsigned NodeIndex : CG.WavefrontOrder)
    emitNodeKernel(OS, CG, NodeIndex);
  emitOutputsKernel(OS, CG);
}

} // namespace texcc::codegen
