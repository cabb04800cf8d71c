// Helpers shared by the generators of every mode (see Emit.h).
#include "Emit.h"

#include "texcc/Graph/Bump.h"
#include "texcc/Graph/Passes.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace texcc::graph;

namespace texcc::codegen {

std::string floatLiteral(double V) {
  // The shortest decimal that reads back as the same float: 0.7f, not 0.699999988f.
  const float F = static_cast<float>(V);
  char Buf[64];
  for (int Digits = 1; Digits <= 9; ++Digits) {
    std::snprintf(Buf, sizeof(Buf), "%.*g", Digits, static_cast<double>(F));
    if (std::strtof(Buf, nullptr) == F)
      break;
  }
  std::string S = Buf;
  if (S.find_first_of(".eEn") == std::string::npos)
    S += ".0";
  return S + "f";
}

std::string intLiteral(double V) {
  return std::to_string(static_cast<long long>(std::llround(V)));
}

std::string vectorCtor(BaseType B, Target T) {
  std::string Name = spelling(B);
  return T == Target::Host ? Name : "(" + Name + ")";
}

std::string constantLiteral(BaseType B, const double *Values, Target T) {
  if (B == BaseType::Int || B == BaseType::Sampler)
    return intLiteral(Values[0]);
  unsigned N = componentCount(B);
  if (N == 1)
    return floatLiteral(Values[0]);
  std::string S = vectorCtor(B, T) + "(";
  for (unsigned I = 0; I < N; ++I)
    S += (I ? ", " : "") + floatLiteral(Values[I]);
  return S + ")";
}

std::string widenToFloat4(BaseType B, const std::string &Expr, Target T) {
  std::string F4 = vectorCtor(BaseType::Float4, T);
  switch (B) {
  case BaseType::Float:
    return F4 + "(" + Expr + ", 0.0f, 0.0f, 0.0f)";
  case BaseType::Float2:
    return F4 + "(" + Expr + ", 0.0f, 0.0f)";
  case BaseType::Float3:
    return F4 + "(" + Expr + ", 0.0f)";
  default:
    return Expr;
  }
}

std::string narrowSwizzle(BaseType B) {
  switch (B) {
  case BaseType::Float:
    return ".x";
  case BaseType::Float2:
    return ".xy";
  case BaseType::Float3:
    return ".xyz";
  default:
    return "";
  }
}

std::string nodeLocalName(const CompiledNode &N, unsigned Index) {
  std::string S = "v" + std::to_string(Index) + "_";
  for (char C : N.Id) {
    if (S.size() >= 32)
      break;
    bool Ok = (C >= 'a' && C <= 'z') || (C >= 'A' && C <= 'Z') || (C >= '0' && C <= '9');
    S += Ok ? C : '_';
  }
  return S;
}

std::string kernelParameterList() {
  return "    __global const TexccHitAttrs *hits,\n"
         "    __global const int *hitMaterial,\n"
         "    int numHits,\n"
         "    __global const uint *fakeStack,\n"
         "    __global const TexccSettings *settings,\n"
         "    __global const float4 *texels,\n"
         "    __global const TexccImageInfo *images,\n"
         "    __global float4 *outputs,\n"
         "    __global float4 *scratch,\n"
         "    __global int *faults";
}

void emitKernelPrologue(std::ostringstream &OS, const std::string &Guard, const std::string &At) {
  OS << "  const int gid = (int)get_global_id(0);\n"
     << "  if (gid >= numHits)\n"
     << "    return;\n"
     << "  const int mat = hitMaterial[gid];\n"
     << "  if (mat < 0 || mat >= TEXCC_NUM_MATERIALS" << Guard << ")\n"
     << "    return;\n"
     << "  TexccCtx ctx;\n"
     << "  ctx.hit = hits[gid];\n"
     << "  ctx.settings = settings;\n"
     << "  ctx.texels = texels;\n"
     << "  ctx.images = images;\n"
     // Field by field: the fault details after badLine stay unset (texcc_device.h).
     << "  TexccGuard guard;\n"
     << "  guard.loopsLeft = TEXCC_LOOP_FIRST_SLICE;\n"
     << "  guard.slicesLeft = TEXCC_LOOP_SLICES;\n"
     << "  guard.at = " << At << ";\n"
     << "  guard.hit = gid;\n"
     << "  guard.material = mat;\n"
     << "  guard.fault = faults;\n"
     << "  guard.line = 0;\n"
     << "  guard.badLine = 0;\n"
     << "  ctx.guard = &guard;\n"
     << "  const TexccCtx *texcc_ctx = &ctx;\n";
}

std::string kernelEpilogue() {
  return "  texcc_report_fault(texcc_ctx);\n";
}

std::string guardAtInstruction(unsigned Instruction) {
  return "texcc_ctx->guard->at = " + std::to_string(Instruction) + "u;";
}

std::string positionOffsetStatement(const CompiledGraph &CG, const CompiledNode &N,
                                    int &Current) {
  if (static_cast<int>(N.PositionOffset) == Current || !usesPositionOffset(CG))
    return "";
  Current = static_cast<int>(N.PositionOffset);
  return "texcc_position_offset(texcc_ctx, " + std::to_string(Current) + ");";
}

std::string signatureComment(const FunctionSignature &Sig) {
  std::string S = spelling(Sig.Return) + " " + Sig.Name + "(";
  for (size_t I = 0; I < Sig.Params.size(); ++I)
    S += (I ? ", " : "") + spelling(Sig.Params[I].Type) + " " + Sig.Params[I].Name;
  return S + ")";
}

uint32_t recordRelativeWord(const CompiledNode &N, const CompiledArg &A) {
  return (sourceWordsBytes(N.Args.size()) + A.BlockOffset) / 4;
}

uint32_t constantWord(const CompiledNode &N, const CompiledArg &A) {
  return N.RecordOffset / 4 + recordRelativeWord(N, A);
}

std::string hostArrayName(unsigned NodeIndex, const CompiledArg &A) {
  return "texcc_array_" + std::to_string(NodeIndex) + "_" + A.Name;
}

/// Word index of hoisted value H in a record of Sig's function, relative to the record.
static uint32_t hoistedRelativeWord(const FunctionSignature &Sig, size_t H) {
  return (sourceWordsBytes(Sig.Params.size()) + hoistedOffsets(Sig).at(H)) / 4;
}

std::vector<std::string> hoistedValueReads(const FunctionSignature &Sig, const std::string &Rec) {
  std::vector<std::string> Reads;
  for (size_t H = 0; H < Sig.Hoisted.size(); ++H)
    Reads.push_back(fakeStackRead(Sig.Hoisted[H].Type,
                                  Rec + " + " + std::to_string(hoistedRelativeWord(Sig, H)) + "u"));
  return Reads;
}

void emitUniformCall(std::ostringstream &OS, const FunctionSignature &Sig,
                     const std::vector<std::string> &Inputs, const std::string &Rec,
                     const std::string &Indent) {
  std::string Call = "texcc_uniform_" + Sig.RenamedName + "(";
  for (size_t I = 0; I < Inputs.size(); ++I)
    Call += (I ? ", " : "") + Inputs[I];
  for (size_t H = 0; H < Sig.Hoisted.size(); ++H) {
    OS << Indent << spelling(Sig.Hoisted[H].Type) << " h" << H << ";\n";
    Call += ", &h" + std::to_string(H);
  }
  OS << Indent << Call << ");\n";
  for (size_t H = 0; H < Sig.Hoisted.size(); ++H) {
    const std::string W = Rec + " + " + std::to_string(hoistedRelativeWord(Sig, H)) + "u";
    const BaseType B = Sig.Hoisted[H].Type;
    if (B == BaseType::Float || B == BaseType::Int)
      OS << Indent << "fakeStack[" << W << "] = as_uint(h" << H << ");\n";
    else
      OS << Indent << "vstore" << componentCount(B) << "(h" << H
         << ", 0, (__global float *)fakeStack + " << W << ");\n";
  }
}

void emitUniformsKernelHead(std::ostringstream &OS) {
  OS << "/* Run once after every upload of args.bin, before texcc_proctex. numMaterials:\n"
     << " * TEXCC_NUM_MATERIALS, or 0 to launch it without work (a warm-up). */\n"
     << "__kernel void " << UniformsEntry
     << "(__global uint *fakeStack, const int numMaterials) {\n"
     << "  if (get_global_id(0) != 0)\n"
     << "    return;\n";
}

std::string fakeStackRead(BaseType B, const std::string &W) {
  switch (B) {
  case BaseType::Float:
    return "as_float(fakeStack[" + W + "])";
  case BaseType::Int:
  case BaseType::Sampler:
    return "as_int(fakeStack[" + W + "])";
  default:
    return "vload" + std::to_string(componentCount(B)) +
           "(0, (__global const float *)fakeStack + " + W + ")";
  }
}

std::string ArgEmitter::argument(const CompiledNode &N, unsigned NodeIndex,
                                 const CompiledArg &A) const {
  const BaseType B = A.Type.Base;
  const std::string Word =
      RecordWord ? RecordWord(NodeIndex) + " + " + std::to_string(recordRelativeWord(N, A)) + "u"
                 : std::to_string(constantWord(N, A)) + "u";
  if (A.Type.IsGlobalArray) {
    if (Tgt == Target::Host)
      return hostArrayName(NodeIndex, A) + ", " + std::to_string(A.ArrayCount) + "u";
    // Relative to a record, the elements' offset is the array's {byteOffset, count} word.
    std::string At =
        RecordWord ? "fakeStack[" + Word + "]" : std::to_string(A.ArrayByteOffset) + "u";
    // Then the array's length, the hidden parameter that bounds-checks its reads (Safety.cpp).
    std::string Length = RecordWord ? "fakeStack[" + Word + " + 1u]"
                                    : std::to_string(A.ArrayCount) + "u";
    return "(__global const " + spelling(B) + " *)((__global const uchar *)fakeStack + " + At +
           "), " + Length;
  }
  std::string E;
  switch (A.Src) {
  case CompiledArg::Source::Constant:
    if (BakeConstants || (BakeMarked && A.Bake))
      return constantLiteral(B, A.Values.data(), Tgt);
    return fakeStackRead(B, Word);
  case CompiledArg::Source::Attribute:
    E = "texcc_attr_" + attributeTable().at(A.AttrId).first + "(texcc_ctx)";
    break;
  case CompiledArg::Source::Node:
    E = ChildExpr(A.NodeIndex);
    break;
  }
  if (A.Broadcast)
    return vectorCtor(B, Tgt) + "(" + E + ")";
  return E;
}

std::string ArgEmitter::call(const CompiledGraph &CG, unsigned NodeIndex,
                             const std::string &Callee, const std::vector<std::string> &Extra) const {
  const CompiledNode &N = CG.Nodes[NodeIndex];
  const std::string &Name = Callee.empty() ? CG.Signatures.at(N.Fn).RenamedName : Callee;
  std::vector<std::string> Args{"texcc_ctx"};
  for (const CompiledArg &A : N.Args)
    Args.push_back(argument(N, NodeIndex, A));
  Args.insert(Args.end(), Extra.begin(), Extra.end());
  size_t Length = Name.size();
  for (size_t I = 1; I < Args.size(); ++I) // texcc_ctx not counted
    Length += Args[I].size() + 2;
  // Long calls get one argument per line.
  const std::string Separator = Length > 72 ? ",\n" + std::string(ArgIndent, ' ') : ", ";
  std::string S = Name + "(";
  for (size_t I = 0; I < Args.size(); ++I)
    S += (I ? Separator : "") + Args[I];
  return S + ")";
}

std::string describeOutputs(const CompiledGraph &CG, const CompiledMaterial &M) {
  std::string S;
  for (size_t K = 0; K < M.Outputs.size(); ++K) {
    const MaterialOutput &O = M.Outputs[K];
    S += (K ? ", " : "") + std::string("out") + std::to_string(K) + " = node " +
         std::to_string(O.Node) + " '" + CG.Nodes[O.Node].Id + "'";
  }
  return S.empty() ? "no texture outputs" : S;
}

} // namespace texcc::codegen
