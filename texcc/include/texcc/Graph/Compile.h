#ifndef TEXCC_GRAPH_COMPILE_H
#define TEXCC_GRAPH_COMPILE_H

// From a parsed graph and the signatures of its functions to what every evaluation mode needs:
// live nodes (unreached removed, identical merged), a DFS topological program per material,
// liveness-based value-stack slots, argument records laid out with OpenCL alignment, and the
// encoded fake stack (args.bin). The byte-level format is specified in docs/abi.md.

#include "texcc/Graph/Graph.h"
#include "texcc/Graph/Signature.h"
#include "texcc/Kernel/Manifest.h"

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace texcc::graph {

/// Where one argument of a quickened pattern comes from (argumentSource()). layout.json spells
/// it "const", "int:N", "slot", "slot.x", "attr:Name" or "attr:Name.x" (spellSource(),
/// parseSource(): the only code that reads or writes that text).
struct ArgumentSource {
  enum class Kind { Constant, IntValue, Slot, Attribute };
  Kind K = Kind::Constant;
  int32_t Value = 0;      // IntValue: the int constant
  int AttrId = -1;        // Attribute: attributeTable() index
  bool Broadcast = false; // Slot, Attribute: a float replicated to a float2..4 parameter
  bool operator==(const ArgumentSource &O) const {
    return K == O.K && Value == O.Value && AttrId == O.AttrId && Broadcast == O.Broadcast;
  }
  bool operator<(const ArgumentSource &O) const {
    if (K != O.K)
      return K < O.K;
    if (Value != O.Value)
      return Value < O.Value;
    if (AttrId != O.AttrId)
      return AttrId < O.AttrId;
    return Broadcast < O.Broadcast;
  }
};

/// A quickened opcode of the interp kernel (docs/modes.md): function Fn with every argument's
/// source fixed (Sources[p]): its case reads each argument straight from where the pattern says
/// (the record's parameter block, the value-stack slot in the source word, an attribute, or,
/// for an int constant, the literal the pattern names, which the compiler folds), with no
/// decoding of the source word's kind.
struct QuickenedOp {
  unsigned Opcode = 0;               // kernel case, after the function ids
  std::string Fn;
  std::vector<ArgumentSource> Sources;  // per parameter
  bool operator==(const QuickenedOp &O) const {
    return Opcode == O.Opcode && Fn == O.Fn && Sources == O.Sources;
  }
};

struct CompileOptions {
  /// Private value-stack cap in float4 slots; beyond it values live in a global spill slice.
  unsigned StackLimit = 32;
  /// Live edits of an interp kernel that hoists (layout.json kernel.uniforms): it calls
  /// texcc_hoisted_<fn> for every node of a function with hoisted values, so an edit that
  /// makes one of their Sig.HoistedFrom parameters a non-constant needs a new kernel.
  bool InterpHoistedCalls = false;
  /// Function ids to keep (live edits: the kernel's switch cases must not move). Functions not
  /// listed get the next free ids.
  std::map<std::string, unsigned> FixedFunctionIds;
  /// Every user function name the sources define (for "did you mean" on an unknown "fn").
  std::vector<std::string> KnownFunctions;
  /// Texture functions of the library (texcc/Frontend/Library.h) -> the file that documents
  /// them ("textures/blender/noise.cl"): an unknown function found here is named with its
  /// file. The driver fills it only when a node names a function no source defines.
  std::map<std::string, std::string> LibraryFunctions;
  /// Where the passes log what they did (texcc -v); null for silence.
  std::ostream *Log = nullptr;
  /// The kernel's quickened opcodes (live edits: layout.json "quickened"), applied wherever an
  /// instruction's pattern matches one (applyQuickened). The graph library never chooses a
  /// table: the interp backend does (texcc/Codegen/Quickening.h), after compileGraph().
  std::vector<QuickenedOp> Quickened;
};

/// One argument of a live node, resolved against the function's signature.
struct CompiledArg {
  enum class Source { Constant, Node, Attribute };
  std::string Name;
  ValueType Type;             // the parameter's type
  Source Src = Source::Constant;
  unsigned NodeIndex = 0;     // Source::Node: index into CompiledGraph::Nodes
  int AttrId = -1;            // Source::Attribute: attributeTable() index
  bool Broadcast = false;     // a float value feeding a float2..4 parameter
  bool Bake = false;          // Source::Constant: a literal in shape code, part of the shape
  /// Source::Constant. Scalars/vectors: Values has componentCount() entries (already
  /// broadcast). Int and sam2D (image index) are stored as floats here and written as int32.
  /// Arrays: Values holds ArrayCount * componentCount(Type.Base) entries, row after row.
  std::vector<double> Values;
  unsigned ArrayCount = 0;
  uint32_t ArrayByteOffset = 0;  // arrays: where the elements start in args.bin
  uint32_t BlockOffset = 0;      // offset of this parameter inside the record's param block
};

struct CompiledNode {
  std::string Id;             // the surviving id (first in file order among merged twins)
  std::vector<std::string> MergedIds;  // ids merged into this one (edits address any of them)
  std::string Fn;
  unsigned FnId = 0;
  BaseType Return = BaseType::Float;
  std::vector<CompiledArg> Args;   // in parameter order
  uint32_t RecordOffset = 0;       // byte offset of the argument record in args.bin
  uint32_t RecordSize = 0;
  SourceLoc Loc;
  /// Further copies of the record, for materials whose stack slots for this node's node
  /// arguments differ from the first material's (the source words differ; the parameter
  /// blocks are identical). Instruction::RecordOffset says which one an instruction uses.
  std::vector<uint32_t> RecordCopies;
  /// Bump (Bump.h): 0, or 1/2 for a copy of a height node that runs with the position moved
  /// along the tangent/bitangent; OffsetOf is the id of the node it copies ("" for a node of
  /// the moved WorldPos/ObjectPos itself), whose edits it follows.
  unsigned PositionOffset = 0;
  std::string OffsetOf;
};

struct Instruction {
  unsigned Node = 0;          // index into CompiledGraph::Nodes
  unsigned ResultSlot = 0;    // value-stack slot that receives the result; may be a slot the
                              // instruction's own arguments read (they are read first)
  uint32_t RecordOffset = 0;  // the argument record it uses (the node's, or one of its copies)
  /// Index into CompiledGraph::Quickened when this instruction runs a quickened opcode (the
  /// fnId word is then its Opcode); -1 otherwise.
  int Quick = -1;
};

/// A BSDF input after compilation: a constant, or a texture output of the material.
struct CompiledBsdfInput {
  std::string Name;           // "color", "roughness", "mask", "strength"
  bool IsOutput = false;
  unsigned Output = 0;        // index into CompiledMaterial::Outputs
  std::vector<double> Constant;  // 1..4 components when !IsOutput
};

struct CompiledBsdf {
  std::string Type;           // diffuse | glossy | mirror | emission | blend
  std::vector<CompiledBsdfInput> Inputs;
  std::vector<std::pair<std::string, CompiledBsdf>> Children;  // blend: "a", "b"
};

struct MaterialOutput {
  unsigned Node = 0;          // index into CompiledGraph::Nodes
  unsigned Slot = 0;          // stack slot holding it at the end of the program
  BaseType Type = BaseType::Float;
};

struct CompiledMaterial {
  std::string Name;
  unsigned Index = 0;
  std::vector<Instruction> Program;   // DFS topological order (children first)
  std::vector<MaterialOutput> Outputs;
  CompiledBsdf Bsdf;
  uint32_t ProgramWordOffset = 0;     // where its encoded program starts, in uint32 words
  unsigned StackSlots = 0;            // this material's peak
};

struct CompiledGraph {
  std::string GraphPath;
  std::vector<std::string> Sources;
  std::vector<std::pair<std::string, std::string>> Images;  // index = image id
  std::map<std::string, std::string> ImageColorSpaces;      // Graph::ImageColorSpaces
  /// Every function a node of the graph names, live or dead: the interpreter (interp mode,
  /// shape mode's fallback) has a switch case for each, so that a rewiring onto any node of
  /// the graph runs on the kernel it has. Inline, wavefront and shape code call only the
  /// functions of live nodes (liveFunctions()).
  SignatureMap Signatures;
  /// FnId -> name, the same functions: the live ones first (in node order), then those only
  /// dead nodes name (in graph.json order). Empty names are gaps (ids pinned by live edits).
  std::vector<std::string> FunctionsById;
  std::vector<QuickenedOp> Quickened;  // the interp kernel's table, opcode order, after the ids
  std::vector<CompiledNode> Nodes;         // live nodes
  /// Every function a node of the graph names (live or dead), in graph.json order of first
  /// use; and the attribute ids that node arguments read (live or dead nodes), sorted: the
  /// interpreter's attribute decoder. Filled by resolveGraph(); node removal keeps them.
  std::vector<std::string> GraphFunctions;
  std::vector<int> GraphArgumentAttributes;
  std::vector<CompiledMaterial> Materials;
  unsigned StackSlots = 0;     // exact peak over all materials (TEXCC_STACK_SLOTS)
  unsigned StackLimit = 0;
  bool Spill = false;          // StackSlots > StackLimit: values in a global slice
  unsigned MaxOutputs = 0;     // TEXCC_MAX_OUTPUTS (at least 1)
  std::vector<std::string> Attributes;  // read by live functions or live node args, sorted
  std::vector<std::string> Settings;    // read by live functions, sorted
  std::vector<unsigned> WavefrontOrder; // node indices, a topological order over all materials
  std::vector<uint8_t> ArgsBin;         // the encoded fake stack (docs/abi.md)
  uint32_t ProgramWords = 0;            // programs occupy words [0, ProgramWords)
  uint32_t RecordsOffset = 0;           // byte offset of the first argument record

  /// The index of the node with this id (also a merged-away id), or -1.
  int findNode(const std::string &Id) const;
  /// The functions of live nodes, sorted (a subset of FunctionsById).
  std::set<std::string> liveFunctions() const;
};

/// Only the validation of compileGraph(): true when there is no error (warnings may be
/// reported).
bool validateGraph(const Graph &G, const SignatureMap &Sigs, const CompileOptions &Opts,
                   DiagnosticSink &Diags);

/// Validates against the signatures (unknown function or argument, missing argument, type
/// mismatch, cycle, dangling reference, unknown image/attribute; unused nodes warn), then runs
/// the passes and encodes args.bin. std::nullopt when any error was reported.
std::optional<CompiledGraph> compileGraph(const Graph &G, const SignatureMap &Sigs,
                                          const CompileOptions &Opts, DiagnosticSink &Diags);

/// The passes and the encoding of compileGraph() on a graph its validation has already
/// resolved (resolveWithBump(), Bump.h, with withBuiltinSignatures(Sigs)): nothing is
/// validated again. The live editor applies a checked edit this way (GraphEditor, Edit.h).
CompiledGraph compileResolved(CompiledGraph Resolved, const SignatureMap &Sigs,
                              const CompileOptions &Opts);

/// The shape of a material's program (shape mode): per instruction its function and, per
/// argument, whether it is a constant (a baked one with its value), which earlier instruction
/// or attribute it reads and whether it is broadcast; then which instructions are the outputs.
/// Constant values other than baked ones, record offsets and stack slots are not part of it:
/// materials of equal keys run the same code on their own records.
std::string shapeKey(const CompiledGraph &CG, const CompiledMaterial &M);

/// The materials that have texture outputs, grouped by shapeKey(), groups in the order of
/// their first material, materials in index order. Shape k's body is texcc_shape_<k>.
struct MaterialShape {
  std::string Key;
  std::vector<unsigned> Materials;
};
std::vector<MaterialShape> groupShapes(const CompiledGraph &CG);

/// What a shape kernel was built for, as 16 hex digits (FNV-1a 64 of every material's
/// shapeKey(), in material order; a material without texture outputs counts as empty). Equal
/// hashes mean the kernel's bodies, its material switch and the materials' program offsets in
/// args.bin (which follow from the program lengths) all still hold: the shape kernel runs the
/// graph with an upload. layout.json kernel.shapeHash; the runtime compares it after an edit.
std::string shapeHash(const CompiledGraph &CG);

/// The graph part of the kernel manifest (docs/abi.md); code generation adds the mode, the
/// kernel's entries and the backend's capabilities.
kernel::Manifest layoutManifest(const CompiledGraph &CG);
/// kernel::writeManifest(layoutManifest(CG)).
std::string layoutJson(const CompiledGraph &CG);

/// The manifest's "quickened" (absent: none), checked against its functions, for the runtime's
/// live edits.
bool readLayoutQuickened(const kernel::Manifest &M, std::vector<QuickenedOp> &Table,
                         std::string &Error);
/// The same from layout.json's text (kernel::readManifest, then the above).
bool readLayoutQuickened(const std::string &LayoutJsonText, std::vector<QuickenedOp> &Table,
                         std::string &Error);

/// The signatures of the manifest's functions (for the runtime's live edits), keyed by name,
/// and the function ids in use.
bool readLayoutSignatures(const kernel::Manifest &M, SignatureMap &Sigs,
                          std::map<std::string, unsigned> &FnIds, std::string &Error);
/// The same from layout.json's text.
bool readLayoutSignatures(const std::string &LayoutJsonText, SignatureMap &Sigs,
                          std::map<std::string, unsigned> &FnIds, std::string &Error);

} // namespace texcc::graph

#endif
