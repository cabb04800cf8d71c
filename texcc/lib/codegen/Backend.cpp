// The backends of the evaluation modes and their registry: the one table that spells the mode
// names. Each backend states its policy here (hoisting, the interpreter's opcode tables, extra
// files); its code generator lives in its own file (Interp.cpp, Inline.cpp, Wavefront.cpp,
// Shape.cpp, Host.cpp).
#include "texcc/Codegen/Backend.h"

#include "Emit.h"
#include "texcc/Codegen/Quickening.h"
#include "texcc/Graph/Passes.h"
#include "texcc/Kernel/Attributes.h"

namespace texcc::codegen {
namespace {

/// The attributes the interpreter's decoder (texcc_interp_attr) has a case for: those the
/// nodes' arguments read, of dead nodes too, and the graph's attribute arguments.
std::vector<std::string> decodedAttributes(const graph::CompiledGraph &CG) {
  std::set<int> Ids(CG.GraphArgumentAttributes.begin(), CG.GraphArgumentAttributes.end());
  for (const graph::CompiledNode &N : CG.Nodes)
    for (const graph::CompiledArg &A : N.Args)
      if (A.Src == graph::CompiledArg::Source::Attribute)
        Ids.insert(A.AttrId);
  std::vector<std::string> Names;
  for (int Id : Ids)
    Names.push_back(kernel::attributeName(static_cast<unsigned>(Id)));
  return Names;
}

/// An interpreter's capabilities (interp, and shape's fallback): values re-encoded in args.bin,
/// a value stack of CG.StackSlots, the decoder's attributes.
kernel::Capabilities interpreterCapabilities(const graph::CompiledGraph &CG) {
  kernel::Capabilities C;
  C.ReEncodes = true;
  C.ValueStackSlots = CG.StackSlots;
  C.DecodedAttributes = decodedAttributes(CG);
  return C;
}

/// An interpreter's user code (interp, and shape's fallback): what every node reaches, with no
/// live node none (no edit can wire one in, as materials are not edited).
void renderInterpreterUserCode(CodegenOptions &Opts, const graph::CompiledGraph &CG,
                               const Backend::UserCodeRenderer &Render) {
  if (CG.Nodes.empty())
    return;
  std::set<std::string> All;
  for (const auto &KV : CG.Signatures)
    All.insert(KV.first);
  Opts.InterpUserCode =
      Render(All, Opts.InterpHoists ? interpHoistingFunctions(CG) : std::set<std::string>{});
}

class InterpBackend final : public Backend {
public:
  const char *name() const override { return "interp"; }
  bool hoists(const BackendOptions &O) const override { return !O.NoHoist; }
  /// The quickened opcodes: the most frequent instruction patterns get a case of their own.
  void finishGraph(graph::CompiledGraph &CG, const BackendOptions &O,
                   std::ostream *Log) const override {
    if (O.MaxQuickened == 0)
      return;
    graph::applyQuickened(CG, chooseQuickened(CG, O.MaxQuickened), Log);
    graph::encodeArgsBin(CG);
  }
  void configureCodegen(CodegenOptions &C, const BackendOptions &O) const override {
    C.InterpHoists = !O.NoHoist;
  }
  bool interprets() const override { return true; }
  void renderUserCode(CodegenOptions &Opts, const graph::CompiledGraph &CG,
                      const UserCodeRenderer &Render) const override {
    Backend::renderUserCode(Opts, CG, Render);
    renderInterpreterUserCode(Opts, CG, Render);
  }
  /// The base's kernel, and the hoisted-value kernel when a function hoists a declaration.
  kernel::KernelEntries entries(const graph::CompiledGraph &CG,
                                const CodegenOptions &Opts) const override {
    kernel::KernelEntries K = Backend::entries(CG, Opts);
    if (Opts.InterpHoists && !CG.Nodes.empty() && !interpHoistingFunctions(CG).empty())
      K.Uniforms = UniformsEntry;
    return K;
  }
  /// The wiring is data (the program in args.bin) and the value stack's depth a -D.
  kernel::Capabilities capabilities(const graph::CompiledGraph &CG,
                                    const CodegenOptions &) const override {
    kernel::Capabilities C = interpreterCapabilities(CG);
    C.WiringIsData = true;
    C.StackHeadroom = true;
    return C;
  }
  const char *summary() const override {
    return "the interpreter: kernel texcc_proctex runs the material's program from fakeStack,\n"
           " *      one switch case per texture function (and per quickened opcode)";
  }
  void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
            const CodegenOptions &Opts) const override {
    emitInterp(OS, CG, Opts.InterpHoists);
  }
};

class InlineBackend final : public Backend {
public:
  const char *name() const override { return "inline"; }
  const char *summary() const override {
    return "per material a straight-line function (constants as literals), and kernel\n"
           " *      texcc_proctex, which switches on the material";
  }
  void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
            const CodegenOptions &) const override {
    emitInline(OS, CG);
  }
};

class WavefrontBackend final : public Backend {
public:
  const char *name() const override { return "wavefront"; }
  /// Every node kernel in launch order, then the outputs kernel (the entry).
  kernel::KernelEntries entries(const graph::CompiledGraph &CG,
                                const CodegenOptions &Opts) const override {
    kernel::KernelEntries K = Backend::entries(CG, Opts);
    K.Entry = WavefrontOutputsEntry;
    for (unsigned N : CG.WavefrontOrder)
      K.Launches.push_back({wavefrontKernelName(N), N});
    return K;
  }
  /// One float4 per node and hit: the node kernels' outputs.
  unsigned scratchFloat4PerHit(const graph::CompiledGraph &CG) const override {
    return static_cast<unsigned>(CG.Nodes.size());
  }
  /// Values in args.bin; the node kernels and their launches are code.
  kernel::Capabilities capabilities(const graph::CompiledGraph &,
                                    const CodegenOptions &) const override {
    kernel::Capabilities C;
    C.ReEncodes = true;
    return C;
  }
  const char *summary() const override {
    return "one kernel texcc_wf_<node> per live node (launch order: layout.json kernel.launches),\n"
           " *      then texcc_wf_outputs";
  }
  void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
            const CodegenOptions &Opts) const override {
    emitWavefront(OS, CG, Opts.WavefrontOnlyFunction, Opts.WavefrontOutputsOnly);
  }
};

/// Shape code, plus the interp kernel of the same graph that the runtime runs while a new
/// shape's kernel builds (without hoisting: texcc_uniforms is the shape kernel's).
class ShapeBackend final : public Backend {
public:
  const char *name() const override { return "shape"; }
  bool hoists(const BackendOptions &O) const override { return !O.NoHoist; }
  bool writesInterpreter() const override { return true; }
  /// The kernel's, the fallback's, and per live function its quick program's (that function's
  /// reach only: a saved source file changes only the programs of the functions it changed).
  void renderUserCode(CodegenOptions &Opts, const graph::CompiledGraph &CG,
                      const UserCodeRenderer &Render) const override {
    Backend::renderUserCode(Opts, CG, Render);
    if (CG.Nodes.empty())
      return;
    for (const std::string &Fn : CG.liveFunctions())
      Opts.QuickUserCode[Fn] = Render({Fn}, {});
    renderInterpreterUserCode(Opts, CG, Render);
  }
  /// The shape kernel, its shapes and hash, its interp fallback and the quick tier's programs
  /// (addOutputs writes their files).
  kernel::KernelEntries entries(const graph::CompiledGraph &CG,
                                const CodegenOptions &Opts) const override {
    kernel::KernelEntries K = Backend::entries(CG, Opts);
    K.InterpFallback = InterpFallbackFile;
    std::vector<graph::MaterialShape> Groups = graph::groupShapes(CG);
    for (size_t I = 0; I < Groups.size(); ++I)
      K.Shapes.push_back({static_cast<unsigned>(I), Groups[I].Materials});
    K.ShapeHash = graph::shapeHash(CG);
    if (!hoistingFunctions(CG).empty())
      K.Uniforms = UniformsEntry;
    if (CG.Nodes.empty())
      return K;
    for (const std::string &Fn : CG.liveFunctions()) {
      kernel::QuickProgram P{quickProgramFile(Fn), {}};
      for (unsigned N : CG.WavefrontOrder)
        if (CG.Nodes[N].Fn == Fn)
          P.Kernels.push_back(wavefrontKernelName(N));
      K.QuickPrograms.push_back(P);
    }
    K.QuickPrograms.push_back({QuickOutputsFile, {WavefrontOutputsEntry}});
    for (unsigned N : CG.WavefrontOrder)
      K.QuickLaunches.push_back({wavefrontKernelName(N), N});
    K.QuickEntry = WavefrontOutputsEntry;
    K.QuickScratchFloat4PerHit = static_cast<unsigned>(CG.Nodes.size());
    return K;
  }
  /// Values in args.bin, code per shape, and the interp fallback of the same args.bin.
  kernel::Capabilities capabilities(const graph::CompiledGraph &CG,
                                    const CodegenOptions &) const override {
    kernel::Capabilities C = interpreterCapabilities(CG);
    C.ShapeKeyed = true;
    C.InterpFallback = true;
    return C;
  }
  std::set<std::string> hoistedInUserCode(const graph::CompiledGraph &CG) const override {
    return hoistingFunctions(CG);
  }
  const char *summary() const override {
    return "per material shape a straight-line body reading its constants from fakeStack\n"
           " *      (layout.json kernel.shapes), and kernel texcc_proctex, which switches on the\n"
           " *      material";
  }
  void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
            const CodegenOptions &) const override {
    emitShape(OS, CG);
  }
  void addOutputs(std::vector<OutputFile> &Files, const graph::CompiledGraph &CG,
                  const CodegenOptions &Opts) const override {
    CodegenOptions Interp = Opts;
    Interp.EvalMode = Mode::Interp;
    Files.push_back({InterpFallbackFile, generateKernel(CG, Interp)});
    // The quick tier (docs/live.md): per live function a wavefront program of its nodes, and
    // the outputs kernel's. A function's program text depends only on its own code (and the
    // graph), so a saved source file changes only the programs of the functions it changed.
    if (CG.Nodes.empty())
      return;
    CodegenOptions Quick = Opts;
    Quick.EvalMode = Mode::Wavefront;
    Quick.InterpUserCode.clear();
    for (const std::string &Fn : CG.liveFunctions()) {
      auto It = Opts.QuickUserCode.find(Fn);
      Quick.UserCode = It == Opts.QuickUserCode.end() ? std::string() : It->second;
      Quick.WavefrontOnlyFunction = Fn;
      Files.push_back({quickProgramFile(Fn), generateKernel(CG, Quick)});
    }
    Quick.UserCode.clear();
    Quick.WavefrontOnlyFunction.clear();
    Quick.WavefrontOutputsOnly = true;
    Files.push_back({QuickOutputsFile, generateKernel(CG, Quick)});
  }
};

/// C++ for the host, whatever the mode: per material a straight-line function.
class HostBackend final : public Backend {
public:
  const char *name() const override { return "host"; }
  /// The extern "C" entry of the C++ file.
  kernel::KernelEntries entries(const graph::CompiledGraph &CG,
                                const CodegenOptions &Opts) const override {
    kernel::KernelEntries K = Backend::entries(CG, Opts);
    K.Entry = HostEntry;
    return K;
  }
  const char *summary() const override {
    return "per material a straight-line C++ function (constants as literals), and the extern \"C\"\n"
           " *      entry texcc_host_evaluate(material, hit, settings, texels, images, outputs)";
  }
  void emit(std::ostringstream &OS, const graph::CompiledGraph &CG,
            const CodegenOptions &) const override {
    emitHost(OS, CG);
  }
};

} // namespace

kernel::KernelEntries Backend::entries(const graph::CompiledGraph &,
                                      const CodegenOptions &Opts) const {
  kernel::KernelEntries K;
  K.Source = kernelFileName(Opts.Tgt);
  K.Entry = KernelEntry;
  return K;
}

void Backend::renderUserCode(CodegenOptions &Opts, const graph::CompiledGraph &CG,
                             const UserCodeRenderer &Render) const {
  Opts.UserCode = Render(CG.liveFunctions(), hoistedInUserCode(CG));
}

unsigned Backend::scratchFloat4PerHit(const graph::CompiledGraph &CG) const {
  return writesInterpreter() && CG.Spill ? CG.StackSlots : 0;
}

kernel::Capabilities Backend::capabilities(const graph::CompiledGraph &,
                                           const CodegenOptions &) const {
  kernel::Capabilities C;
  C.ReEncodes = false;
  return C;
}

namespace {

const InterpBackend Interp;
const InlineBackend Inline;
const WavefrontBackend Wavefront;
const ShapeBackend Shape;
const HostBackend Host;

struct ModeEntry {
  Mode M;
  const Backend *B;
};
/// The registry: every mode, in the order diagnostics list them.
const ModeEntry Modes[] = {{Mode::Interp, &Interp},
                           {Mode::Inline, &Inline},
                           {Mode::Wavefront, &Wavefront},
                           {Mode::Shape, &Shape}};

} // namespace

const Backend &backendFor(Mode M, Target T) {
  if (T == Target::Host)
    return Host;
  for (const ModeEntry &E : Modes)
    if (E.M == M)
      return *E.B;
  return Interp;
}

std::optional<Mode> parseMode(const std::string &S) {
  for (const ModeEntry &E : Modes)
    if (S == E.B->name())
      return E.M;
  return std::nullopt;
}

const char *modeName(Mode M) { return backendFor(M, Target::OpenCL).name(); }

std::string modeNameList() {
  std::string S;
  const size_t N = std::size(Modes);
  for (size_t I = 0; I < N; ++I)
    S += std::string(I == 0 ? "" : I + 1 == N ? " or " : ", ") + Modes[I].B->name();
  return S;
}

} // namespace texcc::codegen
