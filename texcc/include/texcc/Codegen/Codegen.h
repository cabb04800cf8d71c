#ifndef TEXCC_CODEGEN_CODEGEN_H
#define TEXCC_CODEGEN_CODEGEN_H

// Code generation: from a compiled graph and the rendered user code to the texture kernel of one
// evaluation mode (proctex.cl), or to C++ for the host (proctex.cpp), plus layout.json and the
// Graphviz dump. No LLVM: the generators work on graph::CompiledGraph and plain text. The kernel
// ABI (entry points, arguments, args.bin) is docs/abi.md; the modes are docs/modes.md.

#include "texcc/Graph/Compile.h"
#include "texcc/Kernel/Manifest.h"

#include <optional>
#include <set>
#include <map>
#include <string>
#include <vector>

namespace texcc::codegen {

enum class Mode { Interp, Inline, Wavefront, Shape };
enum class Target { OpenCL, Host };

/// "interp" | "inline" | "wavefront" | "shape"; std::nullopt for anything else.
std::optional<Mode> parseMode(const std::string &S);
std::optional<Target> parseTarget(const std::string &S);
const char *modeName(Mode M);
const char *targetName(Target T);

struct CodegenOptions {
  Mode EvalMode = Mode::Interp;
  Target Tgt = Target::OpenCL;
  /// Absolute path of graph.json (layout.json "graph", the kernel's header comment).
  std::string GraphPath;
  /// The user code, already renamed and lowered by the front end and restricted to the functions
  /// reachable from live nodes (TranslatedSource::render(Keep) of every source, concatenated).
  /// For Target::Host it is rewritten by rewriteVectorLiteralsForHost() here.
  std::string UserCode;
  /// The same restricted to the functions reachable from every node's function, live or dead:
  /// the OpenCL interp kernel's (interp mode, shape mode's proctex.interp.cl), which has a case
  /// for each. Empty: UserCode.
  std::string InterpUserCode;
  /// Shape mode's quick tier: per live texture function, the user code it reaches, unhoisted
  /// (its wavefront program, proctex.quick.fn.<fn>.cl).
  std::map<std::string, std::string> QuickUserCode;
  /// Wavefront code of one function's nodes only, without the outputs kernel; or only the
  /// outputs kernel (the quick tier's programs).
  std::string WavefrontOnlyFunction;
  bool WavefrontOutputsOnly = false;
  /// Interp mode: the interp kernel calls texcc_hoisted_<fn> for every function with hoisted
  /// values (interpHoistingFunctions), reading them from the record, and has the kernel
  /// texcc_uniforms that computes them (docs/modes.md). Off for shape mode's fallback.
  bool InterpHoists = false;
  /// --loop-budget: the loop iterations one work-item may run (docs/reliability.md "User
  /// code"); 0: the default of texcc_device.h (TEXCC_LOOP_BUDGET), and no #define is written.
  uint32_t LoopBudget = 0;
  /// --no-checks (hidden, for A/B measurement: bench/per_hit.py): `#define TEXCC_CHECKS 0`,
  /// which makes the loop budget's test always true, so the device compiler drops the checks.
  bool Checks = true;
  /// layout.json "compileOptions": texcc's arguments besides --graph, -o and the sources (the
  /// mode, -I made absolute, -D, the limits, --no-hoist ...), which a live edit's regeneration
  /// passes again so that the new kernel is made the way this one was (docs/abi.md).
  std::vector<std::string> CompileOptions;
  /// layout.json functions[].params[].doc: per texture function, its parameters' rows of the
  /// parameter table in its file's opening comment (frontend::parameterDocs), in parameter
  /// order; what front ends show (docs/abi.md).
  std::map<std::string, std::vector<kernel::ParamDoc>> ParamDocs;
};

/// The entry points every mode's kernel defines (docs/abi.md).
constexpr const char *KernelEntry = "texcc_proctex";          // interp, inline, shape
constexpr const char *WavefrontOutputsEntry = "texcc_wf_outputs";
/// Shape mode, when a node hoists values (layout.json kernel.uniforms): computes them into
/// fakeStack, once per material; the runtime runs it after every upload of args.bin and before
/// the shape kernel's next launch (docs/abi.md).
constexpr const char *UniformsEntry = "texcc_uniforms";
constexpr const char *HostEntry = "texcc_host_evaluate";     // target host (extern "C")
/// "texcc_wf_<NodeIndex>".
std::string wavefrontKernelName(unsigned NodeIndex);

/// The renamed texture functions whose hoisted values some live node computes once per material
/// in shape mode (graph::hoistsUniforms): their texcc_uniform_ and texcc_hoisted_ functions go
/// into the shape kernel.
std::set<std::string> hoistingFunctions(const graph::CompiledGraph &CG);
/// The renamed texture functions of the graph (live or dead nodes') with hoisted values: with
/// CodegenOptions::InterpHoists the interp kernel calls their texcc_hoisted_ functions for
/// every node (the front end hoists only what every node of the function binds to constants).
std::set<std::string> interpHoistingFunctions(const graph::CompiledGraph &CG);

/// "proctex.cl" or "proctex.cpp".
std::string kernelFileName(Target T);
/// Shape mode also writes the interp kernel of the same graph (same args.bin, same entry), which
/// the runtime runs while a new shape's kernel builds (tiered execution): layout.json
/// kernel.interpFallback.
constexpr const char *InterpFallbackFile = "proctex.interp.cl";

/// The generated kernel text: header comment, TEXCC_* macros, the verbatim ABI and device
/// headers (or the host prelude), the user code, then the mode's evaluation code and kernels.
std::string generateKernel(const graph::CompiledGraph &CG, const CodegenOptions &Opts);

/// layout.json: graph::layoutJson() plus "mode", "target", "graph" and "kernel" (the entry
/// points and, for wavefront, the launch plan) and "scratchFloat4PerHit".
std::string generateLayout(const graph::CompiledGraph &CG, const CodegenOptions &Opts);

/// Graphviz dot of the compiled graph: nodes with their arguments (sources, record and parameter
/// offsets), program order and result stack slot per material, material outputs.
std::string generateGraphDot(const graph::CompiledGraph &CG);

/// OpenCL vector literals `(float3)(a, b, c)` parse as a cast of a comma expression in C++;
/// rewrites them (outside comments, strings and character literals) to constructor calls
/// `float3(a, b, c)` for the host target. Everything else is left byte for byte.
std::string rewriteVectorLiteralsForHost(const std::string &Code);

/// The files of one texcc run, by name inside OUTDIR.
struct OutputFile {
  std::string Name;
  std::string Contents;
};

/// proctex.cl|proctex.cpp, proctex.interp.cl (shape mode, OpenCL), layout.json, args.bin, and
/// graph.dot when DumpGraph.
std::vector<OutputFile> generateOutputs(const graph::CompiledGraph &CG,
                                        const CodegenOptions &Opts, bool DumpGraph);

/// Writes every file to a temporary name inside Dir (created if missing), then renames them all
/// into place. On any error the temporaries are removed, earlier outputs stay untouched, Error
/// says why, and the result is false.
bool writeOutputsAtomically(const std::string &Dir, const std::vector<OutputFile> &Files,
                            std::string &Error);

/// The verbatim texts embedded at build time (kernels/common/texcc_abi.h, texcc_device.h, and
/// the host prelude HostPrelude.hpp).
const std::string &abiHeaderText();
const std::string &deviceHeaderText();
const std::string &hostPreludeText();

} // namespace texcc::codegen

#endif
