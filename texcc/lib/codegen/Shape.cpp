// shape: one straight-line body texcc_shape_<k> per distinct material shape (graph::shapeKey:
// the program's functions and wiring, not its constant values); materials of one shape share
// the body. Every unbaked constant is read from the material's own records, found through its
// program in fakeStack (instruction j's record at word prog + 4 + 3j), so shape mode uses
// interp's args.bin unchanged and a parameter edit is an upload. Values live in locals: no value
// stack. Baked arguments ("bake": true, --bake) are literals.
#include "Emit.h"

#include "texcc/Graph/Passes.h"

#include <unordered_map>

using namespace texcc::graph;

namespace texcc::codegen {

static std::string shapeFunctionName(unsigned K) { return "texcc_shape_" + std::to_string(K); }

static std::string materialList(const CompiledGraph &CG, const MaterialShape &S) {
  std::string L;
  for (unsigned M : S.Materials)
    L += (L.empty() ? "" : ", ") + std::to_string(M) + " '" + CG.Materials[M].Name + "'";
  return L;
}

/// Whether the body reads node N's record: an unbaked constant or an array argument.
static bool readsRecord(const CompiledNode &N) {
  for (const CompiledArg &A : N.Args)
    if (A.Src == CompiledArg::Source::Constant && (!A.Bake || A.Type.IsGlobalArray))
      return true;
  return false;
}

/// The body of shape K, written from its first material; locals s<j> and record words r<j> are
/// named by program position j, which is what the materials of a shape have in common.
static void emitShapeBody(std::ostringstream &OS, const CompiledGraph &CG,
                          const MaterialShape &S, unsigned K) {
  const CompiledMaterial &M = CG.Materials[S.Materials.front()];
  OS << "/* shape " << K << ": " << M.Program.size()
     << (M.Program.size() == 1 ? " instruction" : " instructions") << "; materials "
     << materialList(CG, S) << " */\n"
     << "TEXCC_FN static inline void " << shapeFunctionName(K)
     << "(const TexccCtx *texcc_ctx, __global const uint *fakeStack,\n"
     << "    const uint prog, __global float4 *out) {\n";
  std::unordered_map<unsigned, size_t> Position;
  ArgEmitter E;
  E.Tgt = Target::OpenCL;
  E.BakeConstants = false;
  E.BakeMarked = true;
  E.ChildExpr = [&Position](unsigned Child) { return "s" + std::to_string(Position.at(Child)); };
  E.RecordWord = [&Position](unsigned Node) { return "r" + std::to_string(Position.at(Node)); };
  int Offset = -1;
  for (size_t J = 0; J < M.Program.size(); ++J) {
    const unsigned NodeIndex = M.Program[J].Node;
    const CompiledNode &N = CG.Nodes[NodeIndex];
    Position[NodeIndex] = J;
    if (readsRecord(N))
      OS << "  const uint r" << J << " = fakeStack[prog + " << 4 + 3 * J
         << "u] / 4u; /* the record, in words */\n";
    const FunctionSignature &Sig = CG.Signatures.at(N.Fn);
    std::string Call;
    if (hoistsUniforms(N, Sig)) {
      // The values texcc_uniforms computed into the record.
      Call = E.call(CG, NodeIndex, "texcc_hoisted_" + Sig.RenamedName,
                    hoistedValueReads(Sig, "r" + std::to_string(J)));
    } else {
      Call = E.call(CG, NodeIndex);
    }
    const std::string Move = positionOffsetStatement(CG, N, Offset);
    if (!Move.empty())
      OS << "  " << Move << "\n";
    OS << "  " << guardAtInstruction(J) << "\n"
       << "  const " << spelling(N.Return) << " s" << J << " = " << Call << ";\n";
  }
  for (size_t O = 0; O < M.Outputs.size(); ++O) {
    const BaseType T = CG.Nodes[M.Outputs[O].Node].Return;
    OS << "  out[" << O << "] = "
       << widenToFloat4(T, "s" + std::to_string(Position.at(M.Outputs[O].Node)), Target::OpenCL)
       << ";\n";
  }
  OS << "}\n\n";
}

static std::string uniformsFunctionName(unsigned K) {
  return "texcc_uniforms_" + std::to_string(K);
}

/// Whether a node of shape S computes hoisted values.
static bool shapeHoists(const CompiledGraph &CG, const MaterialShape &S) {
  for (const Instruction &In : CG.Materials[S.Materials.front()].Program) {
    const CompiledNode &N = CG.Nodes[In.Node];
    if (hoistsUniforms(N, CG.Signatures.at(N.Fn)))
      return true;
  }
  return false;
}

/// texcc_uniforms_<k>: for each node of shape K that hoists, its texcc_uniform_ function on
/// the node's constants, the results stored after the parameters in the material's record.
static void emitShapeUniforms(std::ostringstream &OS, const CompiledGraph &CG,
                              const MaterialShape &S, unsigned K) {
  const CompiledMaterial &M = CG.Materials[S.Materials.front()];
  OS << "/* shape " << K << ": the values its nodes compute from constants only, once per "
     << "material (kernel texcc_uniforms) */\n"
     << "TEXCC_FN static inline void " << uniformsFunctionName(K)
     << "(__global uint *fakeStack, const uint prog) {\n";
  ArgEmitter E;
  E.Tgt = Target::OpenCL;
  E.BakeConstants = false;
  E.BakeMarked = true;
  for (size_t J = 0; J < M.Program.size(); ++J) {
    const unsigned NodeIndex = M.Program[J].Node;
    const CompiledNode &N = CG.Nodes[NodeIndex];
    const FunctionSignature &Sig = CG.Signatures.at(N.Fn);
    if (!hoistsUniforms(N, Sig))
      continue;
    const std::string R = "r" + std::to_string(J);
    E.RecordWord = [&R](unsigned) { return R; };
    OS << "  { /* node '" << N.Id << "' (" << Sig.Name << ") */\n"
       << "    const uint " << R << " = fakeStack[prog + " << 4 + 3 * J << "u] / 4u;\n";
    std::vector<std::string> Inputs;
    for (unsigned P : Sig.HoistedFrom)
      Inputs.push_back(E.argument(N, NodeIndex, N.Args[P]));
    emitUniformCall(OS, Sig, Inputs, R, "    ");
    OS << "  }\n";
  }
  OS << "}\n\n";
}

/// The kernel texcc_uniforms (docs/abi.md): one work-item computes every material's hoisted
/// values, one material after the other (materials that share a record write the same values).
static void emitUniformsKernel(std::ostringstream &OS, const CompiledGraph &CG,
                               const std::vector<MaterialShape> &Shapes) {
  emitUniformsKernelHead(OS);
  for (unsigned K = 0; K < Shapes.size(); ++K) {
    if (!shapeHoists(CG, Shapes[K]))
      continue;
    for (unsigned Mat : Shapes[K].Materials)
      OS << "  if (numMaterials > " << Mat << ") /* '" << CG.Materials[Mat].Name << "' */\n"
         << "    " << uniformsFunctionName(K) << "(fakeStack, "
         << CG.Materials[Mat].ProgramWordOffset << "u);\n";
  }
  OS << "}\n\n";
}

std::set<std::string> hoistingFunctions(const CompiledGraph &CG) {
  std::set<std::string> Names;
  for (const CompiledNode &N : CG.Nodes) {
    const FunctionSignature &Sig = CG.Signatures.at(N.Fn);
    if (hoistsUniforms(N, Sig))
      Names.insert(Sig.RenamedName);
  }
  return Names;
}

void emitShape(std::ostringstream &OS, const CompiledGraph &CG) {
  const std::vector<MaterialShape> Shapes = groupShapes(CG);
  for (unsigned K = 0; K < Shapes.size(); ++K)
    emitShapeBody(OS, CG, Shapes[K], K);
  if (!hoistingFunctions(CG).empty()) {
    for (unsigned K = 0; K < Shapes.size(); ++K)
      if (shapeHoists(CG, Shapes[K]))
        emitShapeUniforms(OS, CG, Shapes[K], K);
    emitUniformsKernel(OS, CG, Shapes);
  }
  OS << "__kernel void texcc_proctex(\n" << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, "");
  if (Shapes.empty()) {
    OS << "}\n";
    return;
  }
  // Each material's program offset is a literal: it follows from the program lengths of the
  // materials before it, which the shapes fix (graph::shapeHash, kernel.shapeHash). The same
  // value in every lane of a wave makes the body's reads of the records uniform (scalar loads
  // on GPUs, the constants in scalar registers), as the literals of inline code are.
  OS << "  __global float4 *out = outputs + gid * TEXCC_MAX_OUTPUTS;\n"
     << "  switch (mat) {\n";
  for (unsigned K = 0; K < Shapes.size(); ++K)
    for (unsigned Mat : Shapes[K].Materials)
      OS << "  case " << Mat << ": /* '" << CG.Materials[Mat].Name << "' */\n"
         << "    " << shapeFunctionName(K) << "(texcc_ctx, fakeStack, "
         << CG.Materials[Mat].ProgramWordOffset << "u, out);\n"
         << "    break;\n";
  OS << "  default:\n"
     << "    break;\n"
     << "  }\n"
     << kernelEpilogue() << "}\n";
}

} // namespace texcc::codegen
