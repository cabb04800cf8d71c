#ifndef TEXCC_LIB_CODEGEN_EMIT_H
#define TEXCC_LIB_CODEGEN_EMIT_H

// Helpers shared by the generators of every mode: literals, type spellings, the kernel ABI
// argument list, the hit-context setup, and per-node expressions for modes that bake the graph's
// structure into the code (inline, wavefront, host).

#include "texcc/Codegen/Codegen.h"

#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace texcc::codegen {

/// `4.0f`, `-0.5f`, `1e-10f`: the float nearest to V, printed so that it reads back exactly.
std::string floatLiteral(double V);
/// `6`, `-2`: V rounded to an int32.
std::string intLiteral(double V);
/// A constant value of type B as an expression: `0.5f`, `(float3)(1.0f, 2.0f, 3.0f)` (OpenCL) or
/// `float3(1.0f, 2.0f, 3.0f)` (host), `6` for int and sam2D.
std::string constantLiteral(graph::BaseType B, const double *Values, Target T);
/// Widens an expression of type B to float4 (the value stack's and the scratch's element type).
std::string widenToFloat4(graph::BaseType B, const std::string &Expr, Target T);
/// `.x`, `.xy`, `.xyz` or `` (float4): narrows a float4 to B.
std::string narrowSwizzle(graph::BaseType B);
/// A vector constructor prefix: `(float3)` in OpenCL, `float3` on the host.
std::string vectorCtor(graph::BaseType B, Target T);
/// A C identifier made of a node id: `v3_rust_mask` for node 3 with id "rust-mask".
std::string nodeLocalName(const graph::CompiledNode &N, unsigned Index);

/// The kernel parameters of docs/abi.md, identical for every mode, one per line, indented.
std::string kernelParameterList();
/// The common opening of every texture kernel: the work-item's hit, its material (Guard is
/// an extra return condition, may be empty), its safety state `guard` (At: which node runs
/// first, TEXCC_FAULT_AT) and the hit context `texcc_ctx`.
void emitKernelPrologue(std::ostringstream &OS, const std::string &Guard,
                        const std::string &At = "0u");
/// The end of every kernel that runs user code: the work-item's fault, if a check tripped,
/// into the fault record (once, after the nodes: an atomic inside the loops keeps PoCL from
/// vectorizing straight-line kernels, 10x slower).
std::string kernelEpilogue();
/// The statement that tells the guard which node runs next (the fault names it): instruction
/// Instruction of the material's program.
std::string guardAtInstruction(unsigned Instruction);
/// Bump (graph/Bump.h): in a graph that moves the position, the statement that sets the
/// context's position offset for node N when it differs from Current (-1: not set yet), and
/// Current updated; "" otherwise.
std::string positionOffsetStatement(const graph::CompiledGraph &CG, const graph::CompiledNode &N,
                                    int &Current);

/// The parameter/return spelling of a texture function, e.g. "float fbm3(float3 p, int n)".
std::string signatureComment(const graph::FunctionSignature &Sig);

/// The expression of a structural argument of node N (inline, wavefront, host):
/// - Attribute: `texcc_attr_AO(texcc_ctx)`, broadcast with a vector constructor if needed.
/// - Node: ChildExpr(child index), already of the child's return type, broadcast if needed.
/// - Constant: a literal (BakeConstants, or an argument marked "bake" with BakeMarked) or a
///   read of the record's parameter block in `fakeStack` (the argument's value can then change
///   without a rebuild).
/// - Array: a pointer into `fakeStack` (OpenCL: a __global parameter cannot point at a
///   program-scope __constant array) or, on the host, the named static array HostArrayName.
/// Reads from the record use absolute word indices, unless RecordWord is set: then they are
/// relative to RecordWord(node), an expression for the record's first word (shape mode, where
/// one body serves the records of several materials).
struct ArgEmitter {
  Target Tgt = Target::OpenCL;
  bool BakeConstants = true;
  bool BakeMarked = false;
  unsigned ArgIndent = 6;  // continuation indent when a call takes one argument per line
  std::function<std::string(unsigned Child)> ChildExpr;
  std::function<std::string(unsigned NodeIndex)> RecordWord;
  std::string argument(const graph::CompiledNode &N, unsigned NodeIndex,
                       const graph::CompiledArg &A) const;
  /// `fn(texcc_ctx, arg0, arg1, ...)` for node NodeIndex; Callee instead of the renamed
  /// function when given, and Extra after the node's arguments.
  std::string call(const graph::CompiledGraph &CG, unsigned NodeIndex,
                   const std::string &Callee = "", const std::vector<std::string> &Extra = {}) const;
};

/// A value of type B read from fakeStack at word index Word (an expression).
std::string fakeStackRead(graph::BaseType B, const std::string &Word);
/// Hoisting (shape and interp, docs/modes.md): Sig.Hoisted read back from the record at word
/// Rec (an expression), in order, for texcc_hoisted_<fn>.
std::vector<std::string> hoistedValueReads(const graph::FunctionSignature &Sig,
                                           const std::string &Rec);
/// The body of one node's (or instruction's) part of texcc_uniforms: texcc_uniform_<fn> on
/// Inputs (Sig.HoistedFrom's values, in order), its results stored into the record at word Rec
/// after the parameters. Every line starts with Indent.
void emitUniformCall(std::ostringstream &OS, const graph::FunctionSignature &Sig,
                     const std::vector<std::string> &Inputs, const std::string &Rec,
                     const std::string &Indent);
/// The head of kernel texcc_uniforms (abi.md): its comment, signature and the return of every
/// work-item but 0; the caller writes the body and the closing brace.
void emitUniformsKernelHead(std::ostringstream &OS);

/// The name of the static array that holds the host literal of an array argument.
std::string hostArrayName(unsigned NodeIndex, const graph::CompiledArg &A);

/// Word index of a parameter's first constant word inside args.bin.
uint32_t constantWord(const graph::CompiledNode &N, const graph::CompiledArg &A);
/// The same word relative to the record's first word (the same for every node of a function).
uint32_t recordRelativeWord(const graph::CompiledNode &N, const graph::CompiledArg &A);

/// The materials' outputs in a human line: "rusty: out0 = node 2 'mask' (float)".
std::string describeOutputs(const graph::CompiledGraph &CG, const graph::CompiledMaterial &M);

/// "texcc_material_<index>".
std::string materialFunctionName(const graph::CompiledMaterial &M);
/// The straight-line function of one material (inline mode, host target).
void emitStraightLineMaterial(std::ostringstream &OS, const graph::CompiledGraph &CG,
                              const graph::CompiledMaterial &M, Target T);

/// Mode-specific generators (the evaluation code and kernels after the user code).
void emitInterp(std::ostringstream &OS, const graph::CompiledGraph &CG, bool Hoists);
void emitShape(std::ostringstream &OS, const graph::CompiledGraph &CG);
/// `texcc_program(fakeStack, mat)`: the word offset of material mat's program (interp, shape).
void emitProgramLocator(std::ostringstream &OS);
void emitInline(std::ostringstream &OS, const graph::CompiledGraph &CG);
/// OnlyFunction: only the node kernels of that function's nodes and no outputs kernel (a quick
/// program of shape mode); OutputsOnly: only the outputs kernel.
void emitWavefront(std::ostringstream &OS, const graph::CompiledGraph &CG,
                   const std::string &OnlyFunction = "", bool OutputsOnly = false);
/// Shape mode's quick tier (layout.json kernel.quick): the file of function Fn's program, and
/// of the outputs kernel's.
std::string quickProgramFile(const std::string &Fn);
constexpr const char *QuickOutputsFile = "proctex.quick.outputs.cl";
void emitHost(std::ostringstream &OS, const graph::CompiledGraph &CG);

} // namespace texcc::codegen

#endif
