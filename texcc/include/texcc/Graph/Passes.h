#ifndef TEXCC_GRAPH_PASSES_H
#define TEXCC_GRAPH_PASSES_H

// The steps of compileGraph(), exposed one by one so that each can be tested alone (as Cycles
// tests its shader-graph passes): build a small graph, run one pass, look at the result. Each
// pass writes one line per decision to Log when it is not null.

#include "texcc/Graph/Compile.h"

#include <optional>
#include <ostream>

namespace texcc::graph {

/// Validation: resolves every node (file order, nothing removed) and material against the
/// signatures. Nodes keep their graph.json order; material outputs are the distinct nodes the
/// BSDF tree reads, in tree order. Programs, slots and layout are left empty.
std::optional<CompiledGraph> resolveGraph(const Graph &G, const SignatureMap &Sigs,
                                          const CompileOptions &Opts, DiagnosticSink &Diags);

/// Removes nodes that no material output reaches.
void removeUnreachableNodes(CompiledGraph &CG, std::ostream *Log);
/// Merges nodes with the same function and the same arguments (after merging their children):
/// the first in file order survives and records the others in MergedIds.
void mergeIdenticalNodes(CompiledGraph &CG, std::ostream *Log);
/// Function ids: Opts.FixedFunctionIds first, then the next free ids in node order, then in
/// GraphFunctions order for the functions only dead nodes name. Fills Signatures and
/// FunctionsById with all of them, and Attributes, Settings and MaxOutputs from the live nodes.
void assignFunctionIds(CompiledGraph &CG, const SignatureMap &Sigs, const CompileOptions &Opts,
                       std::ostream *Log);
/// Slots a node's evaluation needs (Sethi-Ullman), by node index.
std::vector<unsigned> slotNeeds(const CompiledGraph &CG);
/// A DFS topological program per material, children first; among a node's children the one
/// needing more slots is evaluated first.
void orderPrograms(CompiledGraph &CG, std::ostream *Log);
/// Liveness-based value-stack slots: a slot is free after its last reader; outputs stay live to
/// the end. Sets ResultSlot, output slots, StackSlots (exact peak), StackLimit and Spill.
void allocateStackSlots(CompiledGraph &CG, unsigned StackLimit, std::ostream *Log);
/// A topological order of all live nodes (the wavefront launch order).
void computeWavefrontOrder(CompiledGraph &CG, std::ostream *Log);
/// Parameter blocks (OpenCL alignment), records (16-aligned), record copies, array data,
/// program word offsets.
void layoutArguments(CompiledGraph &CG, std::ostream *Log);
/// The pattern instruction J of material M runs, for a quickened opcode: its function and
/// every argument's source (argumentSource()). Opcode unset.
QuickenedOp instructionPattern(const CompiledGraph &CG, const CompiledMaterial &M, size_t J);
/// Encoding with a given opcode table (interp; docs/modes.md): sets CG.Quickened to Table and
/// marks every instruction whose pattern equals an entry's (Instruction::Quick, the first such
/// entry); the others run their function's plain id. encodeArgsBin() then writes the opcodes.
/// The table is the interp backend's choice (texcc/Codegen/Quickening.h) or, for a live edit,
/// the kernel's, read back from layout.json. Logs the table and each entry's uses.
void applyQuickened(CompiledGraph &CG, std::vector<QuickenedOp> Table, std::ostream *Log);
/// Where argument A of a node comes from, for a quickened pattern: IntValue for an int
/// constant, Constant for other constants and for every sampler or array parameter (always read
/// from the block), else Slot or Attribute (with its broadcast).
ArgumentSource argumentSource(const CompiledArg &A);
/// layout.json's spelling of a source: "const", "int:N", "slot", "slot.x", "attr:Name",
/// "attr:Name.x".
std::string spellSource(const ArgumentSource &S);
/// The reverse; false for any other text (an unknown attribute, an int outside int32).
bool parseSource(const std::string &Text, ArgumentSource &S);
/// Writes ArgsBin from the layout (docs/abi.md).
void encodeArgsBin(CompiledGraph &CG);

/// Byte offsets of one parameter block: the offset of each parameter, and the block size
/// (a multiple of 16; it covers the hoisted values too). Every node of a function shares them
/// (CompiledArg::BlockOffset).
std::vector<uint32_t> parameterOffsets(const FunctionSignature &Sig, uint32_t &BlockSize);
/// Byte offsets of Sig.Hoisted inside the parameter block, after the parameters.
std::vector<uint32_t> hoistedOffsets(const FunctionSignature &Sig);
/// Whether shape code computes Sig.Hoisted of node N once per material: every parameter in
/// Sig.HoistedFrom is a constant at N and not every one of them is baked (baked ones are
/// literals, which the OpenCL compiler folds by itself).
bool hoistsUniforms(const CompiledNode &N, const FunctionSignature &Sig);
/// Bytes of a record's source words, padded to 16: where its parameter block starts, relative
/// to the record (the same for every node of a function).
uint32_t sourceWordsBytes(size_t NumParams);
/// Where the parameter block of a record of N starts.
uint32_t parameterBlockStart(const CompiledNode &N, uint32_t RecordOffset);
/// Writes a constant argument's value into Bin: into the parameter block starting at
/// BlockStart, and for an array its elements at ArrayByteOffset. Nothing for other sources.
void encodeArgumentValue(std::vector<uint8_t> &Bin, uint32_t BlockStart, const CompiledArg &A);
/// The source word of an argument (docs/abi.md), given the slot a node argument reads.
uint32_t sourceWord(const CompiledArg &A, unsigned Slot);

} // namespace texcc::graph

#endif
