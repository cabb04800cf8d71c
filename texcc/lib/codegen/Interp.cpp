// interp: the restricted mega-kernel. Per hit, the material's program in fakeStack is a loop
// over {fnId, resultSlot, recordByteOffset}; every argument is decoded from its source word
// (docs/abi.md); one switch case per texture function of the graph's nodes, live or dead, calls
// it once per node.
#include "Emit.h"

#include "texcc/Graph/Bump.h"
#include "texcc/Graph/Passes.h"

#include <set>

using namespace texcc::graph;

namespace texcc::codegen {

void emitProgramLocator(std::ostringstream &OS) {
  OS << "/* The program of material mat: the blocks of all materials follow each other from word 0\n"
        " * (numInstructions, numOutputs, 3 words per instruction, 1 per output). */\n"
        "TEXCC_FN static inline uint texcc_program(__global const uint *fs, int mat) {\n"
        "  uint at = 0u;\n"
        "  for (int m = 0; m < mat; ++m)\n"
        "    at += 2u + 3u * fs[at] + fs[at + 1u];\n"
        "  return at;\n"
        "}\n\n";
}

/// The member of TexccHitAttrs (kernels/common/texcc_abi.h) that holds attribute Id, widened
/// to float4 as texcc_attr_by_id does.
static std::string hitAttribute(int Id) {
  static const char *const Members[] = {"worldPos", "objectPos", "normal", "geomNormal",
                                        "tangent", "",         "",       "viewDir"};
  if (Id == attributeId("TexCoord0"))
    return "(float4)(h->uvAO.xy, 0.0f, 0.0f)";
  if (Id == attributeId("AO"))
    return "(float4)(h->uvAO.z, 0.0f, 0.0f, 0.0f)";
  if (Id == attributeId("TangentSign"))
    return "(float4)(h->tangent.w, 0.0f, 0.0f, 0.0f)";
  if (Id == attributeId("Backfacing"))
    return "(float4)(h->uvAO.w, 0.0f, 0.0f, 0.0f)";
  return std::string("h->") + Members[Id];
}

/// texcc_interp_attr(h, id): an attribute argument, read from the hit in global memory with a
/// case only for the attributes node arguments (of live or dead nodes) read. texcc_attr_by_id on the private context
/// would keep every attribute of the hit live in registers across the instruction loop (on
/// gfx90a that alone took the kernel from 72 to 99 VGPRs).
static void emitAttributeDecoder(std::ostringstream &OS, const CompiledGraph &CG) {
  // Those of dead nodes too: a rewiring may make them live.
  std::set<int> Ids(CG.GraphArgumentAttributes.begin(), CG.GraphArgumentAttributes.end());
  for (const CompiledNode &N : CG.Nodes)
    for (const CompiledArg &A : N.Args)
      if (A.Src == CompiledArg::Source::Attribute)
        Ids.insert(A.AttrId);
  OS << "/* An attribute argument, widened to float4: only those the nodes' arguments read. */\n"
        "TEXCC_FN static inline float4 texcc_interp_attr(__global const TexccHitAttrs *h, uint id) {\n"
        "  switch (id) {\n";
  for (int Id : Ids)
    OS << "  case " << Id << "u: /* " << attributeTable().at(Id).first << " */\n"
       << "    return " << hitAttribute(Id) << ";\n";
  OS << "  default:\n"
        "    return (float4)(0.0f);\n"
        "  }\n"
        "}\n\n";
}

static void emitDecoder(std::ostringstream &OS, const CompiledGraph &CG) {
  const bool Spill = CG.Spill;
  OS << "/* Where value-stack slot s of this work-item lives: the private array, or (TEXCC_SPILL)\n"
        " * the global scratch slice, slot s of hit gid at s*numHits + gid. */\n";
  if (Spill)
    OS << "#define TEXCC_SLOT(s) scratch[(s) * (uint)numHits + (uint)gid]\n";
  else
    OS << "#define TEXCC_SLOT(s) stack[s]\n";
  OS << "\n";
  emitProgramLocator(OS);
  emitAttributeDecoder(OS, CG);
  const char *StackParam =
      Spill ? "__global const float4 *scratch, int numHits, int gid" : "const float4 *stack";
  OS << "/* Decodes one argument of a float..float4 parameter from its source word src: a constant\n"
        " * of n floats at word at of the record's parameter block, a value-stack slot or an\n"
        " * attribute, widened to float4; the broadcast bit replicates .x (a float feeding a\n"
        " * float2..4 parameter). */\n"
        "TEXCC_FN static inline float4 texcc_arg(__global const TexccHitAttrs *h, __global const uint *fs,\n"
        "                               uint src, uint at, uint n, "
     << StackParam
     << ") {\n"
        "  float4 v;\n"
        "  switch (src >> 30) {\n"
        "  case 1u:\n"
        "    v = TEXCC_SLOT(src & 0xFFFFu);\n"
        "    break;\n"
        "  case 2u:\n"
        "    v = texcc_interp_attr(h, src & 0xFFFFu);\n"
        "    break;\n"
        "  default:\n"
        "    return (float4)(as_float(fs[at]), n > 1u ? as_float(fs[at + 1u]) : 0.0f,\n"
        "                    n > 2u ? as_float(fs[at + 2u]) : 0.0f,\n"
        "                    n > 3u ? as_float(fs[at + 3u]) : 0.0f);\n"
        "  }\n"
        "  return (src & 0x20000000u) ? v.xxxx : v;\n"
        "}\n\n";
}

static bool interpHoists(const FunctionSignature &Sig) {
  return !Sig.Hoisted.empty() && !Sig.HoistedFrom.empty();
}

/// A float..float4 argument read the way a quickened opcode's pattern says (QuickenedOp::Sources):
/// from the block at word At, from the slot in source word P, or the attribute; widened to
/// float4 like texcc_arg's result.
static std::string quickArgument(const ArgumentSource &Source, size_t P, const std::string &At,
                                 BaseType B) {
  std::string V;
  switch (Source.K) {
  case ArgumentSource::Kind::Constant:
  case ArgumentSource::Kind::IntValue: // never for a float parameter (argumentSource)
    return widenToFloat4(B, fakeStackRead(B, At), Target::OpenCL);
  case ArgumentSource::Kind::Slot:
    V = "TEXCC_SLOT(fakeStack[rec + " + std::to_string(P) + "u] & 0xFFFFu)";
    break;
  case ArgumentSource::Kind::Attribute:
    V = "texcc_interp_attr(hits + gid, " + std::to_string(Source.AttrId) + "u)";
    break;
  }
  return Source.Broadcast ? "(" + V + ").xxxx" : V;
}

/// "name: source, ..." of a quickened pattern, for the case's comment.
static std::string patternComment(const FunctionSignature &Sig,
                                  const std::vector<ArgumentSource> &Sources) {
  std::string S;
  for (size_t P = 0; P < Sources.size(); ++P)
    S += (P ? ", " : "") + Sig.Params.at(P).Name + ": " + spellSource(Sources[P]);
  return S;
}

/// The call of one texture function with every argument decoded from the record at word rec,
/// or, for a quickened opcode, read as its pattern Sources says. Parameter block offsets are
/// per function, from its signature (every node of it shares the layout, and a function that
/// only dead nodes name has no node to take them from): the graph library's, never recomputed
/// here.
static std::string interpCall(const FunctionSignature &Sig, bool Hoists,
                              const std::vector<ArgumentSource> *Sources = nullptr) {
  uint32_t BlockSize = 0;
  const std::vector<uint32_t> Offsets = parameterOffsets(Sig, BlockSize);
  const uint32_t SourceWords = sourceWordsBytes(Sig.Params.size()) / 4;
  // With hoisting, the function without its hoisted declarations, their values from the
  // record (texcc_uniforms computed them).
  const bool Hoisted = Hoists && interpHoists(Sig);
  std::string S = (Hoisted ? "texcc_hoisted_" : "") + Sig.RenamedName + "(texcc_ctx";
  for (size_t P = 0; P < Sig.Params.size(); ++P) {
    const ValueType &T = Sig.Params[P].Type;
    std::string At = "rec + " + std::to_string(SourceWords + Offsets[P] / 4) + "u";
    S += ",\n          ";
    if (T.IsGlobalArray)
      S += "(__global const " + spelling(T.Base) +
           " *)((__global const uchar *)fakeStack + fakeStack[" + At + "]), fakeStack[" + At +
           " + 1u]"; // the length: the hidden parameter of the bounds checks
    else if (Sources && Sources->at(P).K == ArgumentSource::Kind::IntValue)
      S += "(" + std::to_string(Sources->at(P).Value) + ")"; // the value the pattern names
    else if (T.Base == BaseType::Int || T.Base == BaseType::Sampler)
      S += "as_int(fakeStack[" + At + "])";
    else if (Sources)
      S += quickArgument(Sources->at(P), P, At, T.Base) + narrowSwizzle(T.Base);
    else
      S += "TEXCC_ARG(" + std::to_string(P) + "u, " + At + ", " +
           std::to_string(componentCount(T.Base)) + "u)" + narrowSwizzle(T.Base);
  }
  if (Hoisted)
    for (const std::string &V : hoistedValueReads(Sig, "rec"))
      S += ",\n          " + V;
  return S + ")";
}

static void emitKernel(std::ostringstream &OS, const CompiledGraph &CG, bool Hoists) {
  OS << "__kernel void texcc_proctex(\n" << kernelParameterList() << ") {\n";
  emitKernelPrologue(OS, "");
  if (!CG.Spill)
    OS << "  float4 stack[TEXCC_STACK_SLOTS];\n";
  OS << "  const uint prog = texcc_program(fakeStack, mat);\n"
        "  const uint numInstructions = fakeStack[prog];\n"
        "  const uint numOutputs = fakeStack[prog + 1u];\n"
        "  for (uint i = 0u; i < numInstructions; ++i) {\n";
  OS << "    const uint fnId = fakeStack[prog + 2u + 3u * i];\n";
  if (usesPositionOffset(CG))
    // Bump (graph/Bump.h): bits 30-31 of the result word, the position offset the node runs
    // with (texcc_position_offset).
    OS << "    const uint resultWord = fakeStack[prog + 3u + 3u * i];\n"
          "    const uint resultSlot = resultWord & 0x3FFFFFFFu;\n"
          "    texcc_position_offset(texcc_ctx, (int)(resultWord >> 30));\n";
  else
    OS << "    const uint resultSlot = fakeStack[prog + 3u + 3u * i];\n";
  OS << "    const uint rec = fakeStack[prog + 4u + 3u * i] / 4u; /* the record, in words */\n"
        "    guard.at = i;\n"
        "    float4 r;\n"
        "    switch (fnId) {\n";
  // Every function a node of the graph names, live or dead: a rewiring onto any node runs on
  // this kernel with a new args.bin.
  const std::set<std::string> Live = CG.liveFunctions();
  for (unsigned Id = 0; Id < CG.FunctionsById.size(); ++Id) {
    auto It = CG.Signatures.find(CG.FunctionsById[Id]);
    if (It == CG.Signatures.end())
      continue; // an id no function of this graph has (pinned by a live edit)
    const FunctionSignature &Sig = It->second;
    OS << "    case " << Id << "u: /* " << signatureComment(Sig) << ", " << Sig.File
       << (Live.count(Sig.Name) ? "" : "; only dead nodes name it") << " */\n"
       << "      r = " << widenToFloat4(Sig.Return, interpCall(Sig, Hoists), Target::OpenCL)
       << ";\n"
       << "      break;\n";
  }
  for (const QuickenedOp &Q : CG.Quickened) {
    auto It = CG.Signatures.find(Q.Fn);
    if (It == CG.Signatures.end())
      continue;
    const FunctionSignature &Sig = It->second;
    OS << "    case " << Q.Opcode << "u: /* quickened " << Sig.Name << " ("
       << patternComment(Sig, Q.Sources) << ") */\n"
       << "      r = "
       << widenToFloat4(Sig.Return, interpCall(Sig, Hoists, &Q.Sources),
                        Target::OpenCL)
       << ";\n"
       << "      break;\n";
  }
  OS << "    default:\n"
        "      r = (float4)(0.0f);\n"
        "      break;\n"
        "    }\n"
        "    TEXCC_SLOT(resultSlot) = r;\n"
        "  }\n"
        "  for (uint k = 0u; k < numOutputs; ++k)\n"
        "    outputs[gid * TEXCC_MAX_OUTPUTS + k] =\n"
        "        TEXCC_SLOT(fakeStack[prog + 2u + 3u * numInstructions + k]);\n"
     << kernelEpilogue() << "}\n";
}

/// texcc_uniforms for the interp kernel: one work-item walks every material's program and, for
/// each instruction whose function hoists (its opcode, or a quickened opcode of it), computes the
/// hoisted values from the record's constants into the record, after the parameters. Driven by
/// the programs in args.bin, so a live edit's re-encoding needs no new kernel.
static void emitInterpUniforms(std::ostringstream &OS, const CompiledGraph &CG) {
  emitUniformsKernelHead(OS);
  OS << "  uint prog = 0u;\n"
     << "  for (int m = 0; m < numMaterials; ++m) {\n"
     << "    const uint numInstructions = fakeStack[prog];\n"
     << "    for (uint i = 0u; i < numInstructions; ++i) {\n"
     << "      const uint rec = fakeStack[prog + 4u + 3u * i] / 4u;\n"
     << "      switch (fakeStack[prog + 2u + 3u * i]) {\n";
  for (unsigned Id = 0; Id < CG.FunctionsById.size(); ++Id) {
    auto It = CG.Signatures.find(CG.FunctionsById[Id]);
    if (It == CG.Signatures.end() || !interpHoists(It->second))
      continue;
    const FunctionSignature &Sig = It->second;
    OS << "      case " << Id << "u: /* " << Sig.Name << " */\n";
    for (const QuickenedOp &Q : CG.Quickened)
      if (Q.Fn == Sig.Name)
        OS << "      case " << Q.Opcode << "u: /* quickened " << Q.Fn << " */\n";
    uint32_t BlockSize = 0;
    const std::vector<uint32_t> Offsets = parameterOffsets(Sig, BlockSize);
    const uint32_t SourceWords = sourceWordsBytes(Sig.Params.size()) / 4;
    std::vector<std::string> Inputs;
    for (unsigned P : Sig.HoistedFrom)
      Inputs.push_back(fakeStackRead(Sig.Params.at(P).Type.Base,
                                     "rec + " + std::to_string(SourceWords + Offsets.at(P) / 4) + "u"));
    OS << "      {\n";
    emitUniformCall(OS, Sig, Inputs, "rec", "        ");
    OS << "        break;\n"
       << "      }\n";
  }
  OS << "      default:\n"
     << "        break;\n"
     << "      }\n"
     << "    }\n"
     << "    prog += 2u + 3u * numInstructions + fakeStack[prog + 1u];\n"
     << "  }\n"
     << "}\n\n";
}

std::set<std::string> interpHoistingFunctions(const CompiledGraph &CG) {
  std::set<std::string> Names;
  for (const auto &KV : CG.Signatures)
    if (interpHoists(KV.second))
      Names.insert(KV.second.RenamedName);
  return Names;
}

void emitInterp(std::ostringstream &OS, const CompiledGraph &CG, bool Hoists) {
  if (CG.Nodes.empty()) {
    // No material has a texture output: nothing to evaluate.
    OS << "__kernel void texcc_proctex(\n" << kernelParameterList() << ") {}\n";
    return;
  }
  emitDecoder(OS, CG);
  const char *Stack = CG.Spill ? "scratch, numHits, gid" : "stack";
  OS << "#define TEXCC_ARG(p, at, n) \\\n"
        "  texcc_arg(hits + gid, fakeStack, fakeStack[rec + (p)], (at), (n), "
     << Stack << ")\n\n";
  Hoists = Hoists && !interpHoistingFunctions(CG).empty();
  if (Hoists)
    emitInterpUniforms(OS, CG);
  emitKernel(OS, CG, Hoists);
}

} // namespace texcc::codegen
