#ifndef TEXCC_KERNEL_MANIFEST_H
#define TEXCC_KERNEL_MANIFEST_H

// The kernel manifest: everything layout.json holds (docs/abi.md), typed, with its one reader and
// one writer. texcc's code generation writes it, the runtime, texcc-eval and the graph editor
// read it; nobody else parses layout.json. No LLVM, Clang nor graph library here.

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace texcc::kernel {

/// The layout version this library writes and reads ("texcc": 1).
inline constexpr unsigned ManifestVersion = 1;

/// What the kernel can absorb without being made again (docs/modes.md, "What an edit costs"),
/// written by the mode's backend into layout.json "capabilities"; the live editor plans with
/// these, never with the mode's name.
struct Capabilities {
  /// A parameter value is in args.bin, which the graph library re-encodes (false: values are
  /// literals of the kernel, every edit regenerates it).
  bool ReEncodes = true;
  /// Any rewiring within the kernel's function set is an upload (the wiring is data).
  bool WiringIsData = false;
  /// The kernel is code per graph shape: an edit that keeps every shape is an upload.
  bool ShapeKeyed = false;
  /// An interp kernel of the same args.bin (kernel.interpFallback) can render while a new
  /// kernel builds (tiered execution).
  bool InterpFallback = false;
  /// The kernel's value stack can be built deeper than the graph needs (stack headroom): its
  /// capacity is a -D at build time.
  bool StackHeadroom = false;
  /// The texture outputs per material the kernel has room for (maxOutputs).
  unsigned MaxOutputs = 1;
  /// The value-stack slots the kernel is generated for (0: no value stack).
  unsigned ValueStackSlots = 0;
  /// The attributes the interpreter's decoder has a case for (empty: no decoder).
  std::vector<std::string> DecodedAttributes;
  /// The kernel that writes the texture outputs (kernel.entry; wavefront: the outputs kernel
  /// that runs after the node kernels).
  std::string OutputsEntry;
  bool operator==(const Capabilities &O) const;
};

/// A BSDF input: a constant or a texture output of the material.
struct BsdfInput {
  bool IsOutput = false;
  int Output = -1;
  std::vector<double> Constant; // 1..4 values
  bool operator==(const BsdfInput &O) const;
};

struct Bsdf {
  std::string Type; // diffuse | glossy | mirror | emission | blend ...
  std::vector<std::pair<std::string, BsdfInput>> Inputs;
  std::vector<std::pair<std::string, Bsdf>> Children; // blend: a, b
  const BsdfInput *input(const std::string &Name) const;
  bool operator==(const Bsdf &O) const;
};

/// A parameter's row of the parameter table in its source file's opening comment
/// (docs/textures.md): what the browser preview's controls show. texcc reads the table; the
/// manifest carries it to the runtime, which sends it to front ends as the edit schema.
struct ParamDoc {
  std::string DefaultText;     // the "default" cell as written ("(0.7, 0.3, 0.2)"; "": none)
  std::vector<double> Default; // that default read for the parameter's type (empty: not a value)
  std::string RangeText;       // the "range" cell as written ("0..1", "> 0", "any")
  std::optional<double> Min, Max; // the numeric bounds the range states
  std::string Text;            // the "meaning" cell
  bool empty() const { return DefaultText.empty() && RangeText.empty() && Text.empty(); }
  bool operator==(const ParamDoc &O) const;
};

/// D as layout.json's functions[].params[].doc spells it (only the cells it has); also what
/// `texcc --list-nodes --json` prints per parameter.
nlohmann::ordered_json paramDocJson(const ParamDoc &D);

struct ParamLayout {
  std::string Name, Type; // Type as OpenCL spells it ("float3", "__global float*")
  unsigned Size = 0, Align = 0, Offset = 0;
  ParamDoc Doc;
  bool operator==(const ParamLayout &O) const;
};

struct HoistedLayout {
  std::string Name, Type;
  unsigned Size = 0, Offset = 0;
  bool operator==(const HoistedLayout &O) const;
};

struct FunctionLayout {
  unsigned Id = 0;
  std::string Name, Renamed, File, Return;
  unsigned BlockSize = 0;
  std::vector<ParamLayout> Params;
  std::vector<std::string> Attributes, Settings;
  unsigned Cost = 0;
  bool HasHoisted = false; // "hoisted" present
  std::vector<HoistedLayout> Hoisted;
  std::vector<std::string> HoistedFrom; // parameter names
  bool operator==(const FunctionLayout &O) const;
};

/// A quickened opcode of the interpreter: a function with its argument sources fixed.
struct QuickenedLayout {
  unsigned Opcode = 0;
  std::string Function;
  std::vector<std::string> Sources; // "const", "slot", "slot.x", "attr:Name", "int:N", ...
  /// A quickened superinstruction of a texcc before 2026-12 ("second"): only its opcode counts.
  bool Legacy = false;
  std::string Second;
  bool operator==(const QuickenedLayout &O) const;
};

struct ArgLayout {
  enum class Source { Attribute, Node, Constant };
  std::string Name;
  Source Src = Source::Constant;
  std::string Attr;       // Attribute
  unsigned Node = 0;      // Node: index into Manifest::Nodes
  bool Broadcast = false; // Attribute, Node
  std::string Image;      // Constant sampler: the image's name ("" when none)
  bool IsArray = false;   // Constant __global array: at ArrayOffset, ArrayCount elements
  unsigned ArrayOffset = 0, ArrayCount = 0;
  bool IntValue = false;  // Constant: Value written as integers
  std::vector<double> Value;
  bool Bake = false;      // baked on texcc's command line (--bake)
  unsigned Offset = 0;    // in the node's record
  bool operator==(const ArgLayout &O) const;
};

struct NodeLayout {
  unsigned Index = 0;
  std::string Id;
  std::vector<std::string> Merged;
  std::string Fn;
  unsigned FnId = 0;
  unsigned RecordOffset = 0, RecordSize = 0;
  std::vector<unsigned> Copies; // the record's copies per material (args.bin offsets)
  std::vector<ArgLayout> Args;
  bool operator==(const NodeLayout &O) const;
};

struct OutputLayout {
  unsigned Node = 0, Slot = 0;
  std::string Type; // float | float2 | float3 | float4
  unsigned components() const;
  bool operator==(const OutputLayout &O) const;
};

struct MaterialLayout {
  std::string Name;
  int Index = 0;
  unsigned ProgramWordOffset = 0, ProgramInstructions = 0, ProgramStackSlots = 0;
  std::vector<OutputLayout> Outputs;
  Bsdf Surface;
  bool operator==(const MaterialLayout &O) const;
};

struct ImageLayout {
  std::string Name, Path; // Path as written (absolute, or relative to the layout's folder)
  unsigned Index = 0;
  std::string ColorSpace; // graph.json's "colorspace"; empty: the file's default
  bool operator==(const ImageLayout &O) const;
};

struct ShapeLayout {
  unsigned Id = 0;
  std::vector<unsigned> Materials;
  bool operator==(const ShapeLayout &O) const;
};

struct LaunchLayout {
  std::string Kernel;
  unsigned Node = 0;
  bool operator==(const LaunchLayout &O) const;
};

/// Shape mode's quick tier (kernel.quick, docs/live.md): one program per live texture function
/// holding that function's wavefront node kernels (and the user code it reaches), plus one for
/// the outputs kernel; after a saved source file the runtime rebuilds only the programs whose
/// text changed.
struct QuickProgram {
  std::string Source;               // the program's file, in the texture folder
  std::vector<std::string> Kernels; // its node kernels (or the outputs kernel)
  bool operator==(const QuickProgram &O) const;
};

/// The roles of a kernel's programs. primary: the layout's own kernel (kernel.source: its
/// launches, entry and uniforms kernel); fallback: an interp kernel of the same args.bin that
/// renders while a new primary builds (kernel.interpFallback, shape mode); quick: shape mode's
/// quick tier, one program per live function plus the outputs kernel's (kernel.quick.programs).
/// layout.json keeps its keys; KernelEntries::programs() is the view by role.
enum class ProgramRole { Primary, Fallback, Quick };
/// "primary", "fallback", "quick".
const char *programRoleName(ProgramRole R);

/// One program of a kernel: its role, its file (relative to the texture folder) and the kernels
/// it holds, in launch order.
struct RoleProgram {
  ProgramRole Role = ProgramRole::Primary;
  std::string Source;
  std::vector<std::string> Kernels;
  bool operator==(const RoleProgram &O) const;
};

/// kernel: the entry points.
struct KernelEntries {
  std::string Source = "proctex.cl";
  std::string Entry = "texcc_proctex";
  std::string InterpFallback;       // shape mode: the interp kernel's file
  std::vector<ShapeLayout> Shapes;  // shape mode
  std::string ShapeHash;            // shape mode
  std::string Uniforms;             // the hoisted-value kernel ("" when none)
  std::vector<LaunchLayout> Launches; // wavefront: node kernels in order; Entry runs last
  std::vector<QuickProgram> QuickPrograms; // shape mode: the quick tier's programs
  std::vector<LaunchLayout> QuickLaunches; // their node kernels in order; QuickEntry runs last
  std::string QuickEntry;                  // the quick tier's outputs kernel
  unsigned QuickScratchFloat4PerHit = 0;   // node values per hit the quick tier keeps
  /// Every program by role: the primary (Launches' kernels, Entry, then Uniforms when set),
  /// the fallback when InterpFallback names one (Entry), the quick programs in their order.
  std::vector<RoleProgram> programs() const;
  /// Those of role R only.
  std::vector<RoleProgram> programs(ProgramRole R) const;
  bool operator==(const KernelEntries &O) const;
};

struct Manifest {
  unsigned Version = ManifestVersion;
  std::string Mode;   // interp | inline | wavefront | shape
  std::string Target = "opencl";
  std::string Graph;  // graph.json the kernel was made from, as written
  /// texcc's arguments besides --graph, -o and the sources, replayed by a regeneration (a
  /// layout of a texcc before "compileOptions": {"--mode=" + Mode}; HasCompileOptions false).
  std::vector<std::string> CompileOptions;
  bool HasCompileOptions = true;
  KernelEntries Kernel;
  /// The backend's capabilities (a kernel layout without the block is refused; a graph-only
  /// layout has none: HasCapabilities false).
  Capabilities Caps;
  bool HasCapabilities = true;
  unsigned ScratchFloat4PerHit = 0;
  unsigned StackSlots = 0;
  unsigned StackLimit = 32;
  bool Spill = false;
  std::string ValueStack = "private"; // private | local | global
  unsigned MaxOutputs = 1;
  std::optional<uint64_t> ArgsBinSize;
  unsigned ProgramWords = 0, RecordsOffset = 0;
  std::vector<std::string> Attributes, Settings;
  std::vector<ImageLayout> Images;
  std::vector<FunctionLayout> Functions;
  std::vector<QuickenedLayout> Quickened;
  /// Opcodes of the superinstructions of a texcc before 2026-12 (read, never written).
  std::vector<unsigned> LegacySuperinstructions;
  std::vector<NodeLayout> Nodes;
  std::vector<unsigned> WavefrontOrder;
  std::vector<MaterialLayout> Materials;
  bool operator==(const Manifest &O) const;
};


/// A reading error: where (file:line:col when the position is known) and why.
struct ManifestError {
  std::string File;
  unsigned Line = 0, Column = 0; // 1-based; 0: unknown
  std::string Pointer;           // JSON pointer of the field ("/kernel/entry"), "" for syntax
  std::string Message;
  /// "FILE:LINE:COL: /pointer: message".
  std::string str() const;
};

/// Reads layout.json's text; File names it in errors. Returns false and sets Error on malformed
/// input (syntax, a missing or mistyped field, an unknown version or mode).
bool readManifest(const std::string &Text, const std::string &File, Manifest &Out,
                  ManifestError &Error);
/// Reads the file at Path.
bool readManifestFile(const std::string &Path, Manifest &Out, ManifestError &Error);

/// layout.json's text (2-space indentation, a final newline).
std::string writeManifest(const Manifest &M);

} // namespace texcc::kernel

#endif
