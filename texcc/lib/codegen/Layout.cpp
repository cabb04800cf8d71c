// layout.json: the graph library's part of the manifest (graph::layoutManifest) plus what code
// generation decides: the mode, the target, the kernel entry points and launch plan, the scratch
// size per hit, and the backend's capabilities; written by the kernel library (writeManifest).
#include "Emit.h"
#include "texcc/Codegen/Backend.h"

using namespace texcc::graph;

namespace texcc::codegen {

/// kernel: the entry points, the shapes and launch plan.
static kernel::KernelEntries kernelEntries(const CompiledGraph &CG, const CodegenOptions &Opts) {
  kernel::KernelEntries K;
  K.Source = kernelFileName(Opts.Tgt);
  if (Opts.Tgt == Target::Host) {
    K.Entry = HostEntry;
    return K;
  }
  if (Opts.EvalMode == Mode::Shape) {
    K.Entry = KernelEntry;
    K.InterpFallback = InterpFallbackFile;
    std::vector<MaterialShape> Groups = groupShapes(CG);
    for (size_t I = 0; I < Groups.size(); ++I)
      K.Shapes.push_back({static_cast<unsigned>(I), Groups[I].Materials});
    K.ShapeHash = shapeHash(CG);
    if (!hoistingFunctions(CG).empty())
      K.Uniforms = UniformsEntry;
    if (!CG.Nodes.empty()) { // the quick tier (Backend.cpp, ShapeBackend::addOutputs)
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
    }
    return K;
  }
  if (Opts.EvalMode != Mode::Wavefront) {
    K.Entry = KernelEntry;
    if (Opts.EvalMode == Mode::Interp && Opts.InterpHoists && !CG.Nodes.empty() &&
        !interpHoistingFunctions(CG).empty())
      K.Uniforms = UniformsEntry;
    return K;
  }
  // Wavefront: every node kernel in launch order, then the outputs kernel ("entry").
  K.Entry = WavefrontOutputsEntry;
  for (unsigned N : CG.WavefrontOrder)
    K.Launches.push_back({wavefrontKernelName(N), N});
  return K;
}

static unsigned scratchFloat4PerHit(const CompiledGraph &CG, const CodegenOptions &Opts) {
  if (Opts.Tgt == Target::Host)
    return 0;
  if (Opts.EvalMode == Mode::Wavefront)
    return static_cast<unsigned>(CG.Nodes.size());
  // Shape mode: for its interp fallback (the shape kernel itself needs no scratch).
  if ((Opts.EvalMode == Mode::Interp || Opts.EvalMode == Mode::Shape) && CG.Spill)
    return CG.StackSlots;
  return 0;
}

std::string generateLayout(const CompiledGraph &CG, const CodegenOptions &Opts) {
  kernel::Manifest M = layoutManifest(CG);
  M.Mode = modeName(Opts.EvalMode);
  M.Target = targetName(Opts.Tgt);
  M.Graph = Opts.GraphPath;
  M.CompileOptions = Opts.CompileOptions;
  M.Kernel = kernelEntries(CG, Opts);
  M.ScratchFloat4PerHit = scratchFloat4PerHit(CG, Opts);
  // Spilling is an interpreter matter: other modes have no value stack (shape mode keeps it for
  // its interp fallback).
  const bool Interprets = Opts.EvalMode == Mode::Interp || Opts.EvalMode == Mode::Shape;
  if (!Interprets || Opts.Tgt == Target::Host)
    M.Spill = false;
  M.Caps = backendFor(Opts).capabilities(CG, Opts);
  M.Caps.MaxOutputs = M.MaxOutputs;
  M.Caps.OutputsEntry = M.Kernel.Entry;
  return kernel::writeManifest(M);
}

} // namespace texcc::codegen
