#ifndef TEXCC_CODEGEN_BACKEND_H
#define TEXCC_CODEGEN_BACKEND_H

// The evaluation modes as backends (docs/modes.md): interp, inline, wavefront, shape and the
// host target, a closed set behind one interface. A backend owns what only its kernel needs
// (the interpreter's opcode tables and hoisting, shape mode's fallback kernel) and answers the
// questions the driver would otherwise answer by comparing mode names. The registry in
// Backend.cpp is the only place the mode names are spelled.

#include "texcc/Codegen/Codegen.h"
#include "texcc/Kernel/Manifest.h"

#include <functional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace texcc::codegen {

/// The options a backend reads (texcc's command line; a backend ignores those it has no use
/// for, as --max-quickened means nothing to inline code).
struct BackendOptions {
  /// --no-hoist: no declaration of the user's functions computed once per material.
  bool NoHoist = false;
  /// interp: the quickened opcodes' budget (--max-quickened).
  unsigned MaxQuickened = 8;
};

class Backend {
public:
  virtual ~Backend() = default;
  /// The mode's name as texcc's --mode spells it ("host" for the host target).
  virtual const char *name() const = 0;
  /// Whether the front end should compute the hoistable declarations of the user's functions
  /// (docs/frontend.md, "Hoisting"): the backend calls texcc_hoisted_ functions.
  virtual bool hoists(const BackendOptions &) const { return false; }
  /// What this backend does to the compiled graph for its kernel only, after compileGraph()
  /// (interp: chooses its quickened opcodes, texcc/Codegen/Quickening.h, and encodes args.bin
  /// with them). Logs its decisions to Log (texcc -v) when not null.
  virtual void finishGraph(graph::CompiledGraph &, const BackendOptions &,
                           std::ostream * /*Log*/) const {}
  /// Sets this backend's part of the code generator's options.
  virtual void configureCodegen(CodegenOptions &, const BackendOptions &) const {}
  /// Whether the kernel is the interpreter, whose switch holds the functions of dead nodes too
  /// (CodegenOptions::InterpUserCode).
  virtual bool interprets() const { return false; }
  /// Whether the outputs include an interpreter kernel: interp, and shape for its fallback.
  virtual bool writesInterpreter() const { return interprets(); }
  /// The renamed functions whose hoisted declarations the kernel's straight-line code reads
  /// from the record (their texcc_uniform_/texcc_hoisted_ pair goes into the user code).
  virtual std::set<std::string> hoistedInUserCode(const graph::CompiledGraph &) const {
    return {};
  }
  /// The user's sources with only the user functions that the texture functions Textures
  /// reach, the declarations of the renamed functions Hoist hoisted (the driver's front end
  /// renders them; the backend says which it needs).
  using UserCodeRenderer = std::function<std::string(const std::set<std::string> &Textures,
                                                     const std::set<std::string> &Hoist)>;
  /// Fills Opts' user code for every program this backend writes: UserCode (the kernel: what
  /// live nodes reach), and for a backend that writes an interpreter InterpUserCode (what every
  /// node reaches: a rewiring onto a dead node is then an upload, not a rebuild); shape mode
  /// adds QuickUserCode (one per live function, for its quick-tier program).
  virtual void renderUserCode(CodegenOptions &Opts, const graph::CompiledGraph &CG,
                              const UserCodeRenderer &Render) const;
  /// The header comment's line on what the evaluation code does.
  virtual const char *summary() const = 0;
  /// The evaluation code and kernels, after the user code.
  virtual void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
                    const CodegenOptions &Opts) const = 0;
  /// What this backend's kernel of CG can absorb without being made again (layout.json
  /// "capabilities", docs/abi.md): the runtime plans edits with it, never with the mode's name.
  /// The base: values are literals (every edit regenerates), no value stack, no decoder.
  virtual kernel::Capabilities capabilities(const graph::CompiledGraph &CG,
                                            const CodegenOptions &Opts) const;
  /// layout.json's "kernel" block: the entry points and whatever launch plan the kernel needs.
  /// The base: one kernel texcc_proctex in the target's kernel file.
  virtual kernel::KernelEntries entries(const graph::CompiledGraph &CG,
                                        const CodegenOptions &Opts) const;
  /// Scratch float4s per hit the runtime allocates: the base, an interpreter's spilled value
  /// stack (interp, and shape for its fallback), else none.
  virtual unsigned scratchFloat4PerHit(const graph::CompiledGraph &CG) const;
  /// Files besides the kernel, layout.json and args.bin (shape: its interp fallback kernel).
  virtual void addOutputs(std::vector<OutputFile> &, const graph::CompiledGraph &,
                          const CodegenOptions &) const {}
};

/// The backend that generates Opts' kernel: the host target's for Target::Host (whatever the
/// mode), else the mode's.
const Backend &backendFor(Mode M, Target T);
inline const Backend &backendFor(const CodegenOptions &Opts) {
  return backendFor(Opts.EvalMode, Opts.Tgt);
}

/// "interp, inline, wavefront or shape": the modes for a diagnostic.
std::string modeNameList();

} // namespace texcc::codegen

#endif
