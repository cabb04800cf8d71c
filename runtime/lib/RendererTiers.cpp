// The texture kernel of a Renderer: building it, and for shape-mode layouts the two tiers
// (TextureTiers.h): the interp fallback renders while the shape kernel builds on a background
// thread, and frames switch to the shape kernel at the first frame after it is ready.

#include "texrender/Error.h"
#include "texrender/Renderer.h"

#include <cstdio>

namespace texrender {

Renderer::~Renderer() {
  if (Pending)
    Pending->wait();
  for (auto &R : Retired)
    R->wait();
}

cl::Program Renderer::buildForeground(const std::string &Path, const std::string &Source,
                                      const std::string &Tier, const std::string &Reason,
                                      const std::string &ExtraOptions) {
  BuildEvent E;
  E.Kernel = Tier;
  E.Reason = Reason;
  E.StartSeconds = steadySeconds() - Epoch;
  cl::Program P = Cl->buildProgram(Path, Source, programOptions() + ExtraOptions);
  // PoCL's compile at the first launch is part of the build the frame waits for.
  std::vector<std::string> Names = textureKernelNames();
  if (tierUsesUniforms(Tier))
    Names.push_back(Lay.Uniforms);
  warmUpKernels(*Cl, P, Names, Path);
  E.ReadySeconds = steadySeconds() - Epoch;
  E.FirstFrame = int(FramesRendered);
  Events.push_back(E);
  return P;
}

bool Renderer::tierUsesUniforms(const std::string &Tier) const {
  // The layout's own kernel (shape mode's shape tier, or an interp-mode kernel that hoists);
  // shape mode's interp fallback never reads hoisted values.
  return !Lay.Uniforms.empty() && !(Lay.Caps.InterpFallback && Tier == FallbackTierName);
}

std::vector<std::string> Renderer::textureKernelNames() const {
  // Wavefront: every node kernel in launch order, then the outputs kernel (kernel.entry).
  std::vector<std::string> Names = Lay.WavefrontLaunches;
  Names.push_back(Lay.Entry);
  return Names;
}

double Renderer::foregroundBuildSeconds() const {
  double S = 0;
  for (const BuildEvent &E : Events)
    if (!E.Background && E.ReadySeconds >= 0)
      S += E.ReadySeconds - E.StartSeconds;
  return S;
}

void Renderer::activate(const cl::Program &P, const std::string &Tier) {
  TextureKernels.clear();
  ActiveTier = Tier;
  TextureKernelNames = textureKernelNames();
  std::string File =
      Lay.Caps.InterpFallback && Tier == FallbackTierName ? Lay.InterpFallback : Lay.KernelSource;
  for (const std::string &N : TextureKernelNames) {
    try {
      TextureKernels.push_back(cl::Kernel(P, N.c_str()));
    } catch (const cl::Error &E) {
      throw Error(File + ": no kernel '" + N + "' in the texture program (" +
                  clErrorName(E.err()) + ")");
    }
  }
  UniformsKernel = cl::Kernel();
  UniformsDirty = true;
  if (tierUsesUniforms(Tier)) {
    try {
      UniformsKernel = cl::Kernel(P, Lay.Uniforms.c_str());
    } catch (const cl::Error &E) {
      throw Error(File + ": no kernel '" + Lay.Uniforms + "' in the texture program (" +
                  clErrorName(E.err()) + ")");
    }
  }
}

void Renderer::buildTextureKernel() {
  supersedePending();
  TextureKernels.clear();
  TextureKernelNames.clear();
  ShapeProgram = InterpProgram = cl::Program();
  ActiveTier.clear();
  if (!HasTextureWork)
    return;
  const char *Reason = FramesRendered ? "edit" : "initial";
  if (!Lay.Caps.InterpFallback) {
    InterpModeSlots = Lay.StackSlots;
    const std::string Source = readKernelSource(Lay.KernelSource);
    const std::string Headroom = Lay.Caps.StackHeadroom && Opts.InterpStackHeadroom
                                     ? stackHeadroomOption(Lay, Source, InterpModeSlots)
                                     : "";
    activate(buildForeground(Lay.KernelSource, Source, Lay.Mode, Reason, Headroom), Lay.Mode);
    return;
  }
  buildShapeTiers(Reason);
}

void Renderer::buildShapeTiers(const char *Reason) {
  // Something must render the next frame. A kernel whose binary is cached is a load, not a
  // build: use it. With neither cached, tier auto builds the shape kernel first (on PoCL it
  // builds faster than the fallback, whose switch holds every function) and the fallback
  // behind it, for later rewirings.
  const TierPolicy P = Opts.Tier;
  const std::string ShapeText = readKernelSource(Lay.KernelSource);
  const std::string FallbackText = readKernelSource(Lay.InterpFallback);
  const std::string FallbackHeadroom = stackHeadroomOption(Lay, FallbackText, FallbackSlots);
  const bool ShapeCached = Cl->isCached(ShapeText, programOptions());
  const bool FallbackCached = Cl->isCached(FallbackText, programOptions() + FallbackHeadroom);
  const bool Auto = P == TierPolicy::Auto;
  if (P == TierPolicy::Shape || (Auto && (ShapeCached || !FallbackCached)))
    ShapeProgram = buildForeground(Lay.KernelSource, ShapeText, ShapeTierName, Reason);
  if (P == TierPolicy::Interp || (Auto && FallbackCached))
    InterpProgram = buildForeground(Lay.InterpFallback, FallbackText, FallbackTierName, Reason,
                                    FallbackHeadroom);
  activate(ShapeProgram() ? ShapeProgram : InterpProgram,
             ShapeProgram() ? ShapeTierName : FallbackTierName);
  if (Auto && (!ShapeProgram() || !InterpProgram())) {
    Layout Same = Lay;
    TierJob Job{/*SameLayout=*/true, /*Shape=*/!ShapeProgram(), /*Interp=*/!InterpProgram()};
    startBackgroundBuild([Same] { return Same; }, Job, nullptr, Reason);
  }
}

void Renderer::switchShapes(const std::vector<uint8_t> &ArgsBin,
                            const std::vector<std::string> &Attributes,
                            std::function<Layout()> MakeLayout,
                            std::function<void(Layout &)> Reencode) {
  if (!Lay.Caps.InterpFallback || !InterpProgram())
    throw Error("switchShapes: needs a shape-mode layout with its interp fallback built (tier auto)");
  applyArguments(ArgsBin, Attributes);
  if (HasTextureWork && ActiveTier != FallbackTierName)
    activate(InterpProgram, FallbackTierName);
  startBackgroundBuild(std::move(MakeLayout), TierJob{false, true, true}, std::move(Reencode),
                       "shape change");
}

void Renderer::startBackgroundBuild(std::function<Layout()> MakeLayout, TierJob Job,
                                    std::function<void(Layout &)> Reencode,
                                    const std::string &Reason) {
  supersedePending();
  Queued = QueuedBuild{std::move(MakeLayout), Job, std::move(Reencode), Reason};
  launchQueued();
}

void Renderer::launchQueued() {
  // One build thread at a time: a superseded build cannot be cancelled, and letting it finish
  // before the next one starts keeps rapid edits from piling up builds on the same cores.
  reapRetired(false);
  if (!Queued || Pending || !Retired.empty())
    return;
  BuildEvent E;
  E.Kernel = Queued->Job.Shape ? ShapeTierName : FallbackTierName;
  E.Reason = Queued->Reason;
  E.Background = true;
  E.StartSeconds = steadySeconds() - Epoch;
  Events.push_back(E);
  ClContext *Ctx = Cl.get();
  std::string Options = programOptions();
  double Start = Epoch;
  Pending = std::make_unique<BackgroundBuild>(
      [Ctx, MakeLayout = std::move(Queued->MakeLayout), Job = Queued->Job, Options, Start] {
        return buildShapeTier(*Ctx, MakeLayout, Job, Options, Start);
      },
      Events.size() - 1);
  PendingReencode = std::move(Queued->Reencode);
  Queued.reset();
}

void Renderer::supersedePending() {
  Queued.reset();
  if (!Pending)
    return;
  Events[Pending->eventIndex()].Superseded = true;
  Retired.push_back(std::move(Pending));
  PendingReencode = nullptr;
}

void Renderer::reapRetired(bool Wait) {
  for (auto It = Retired.begin(); It != Retired.end();) {
    if (!Wait && !(*It)->ready()) {
      ++It;
      continue;
    }
    TierBuildResult R = (*It)->take();
    BuildEvent &E = Events[(*It)->eventIndex()];
    E.ReadySeconds = R.ReadySeconds;
    E.Error = R.Error;
    It = Retired.erase(It);
  }
}

void Renderer::adoptReadyBuild() {
  launchQueued();
  if (!Pending || !Pending->ready())
    return;
  TierBuildResult R = Pending->take();
  BuildEvent &E = Events[Pending->eventIndex()];
  Pending.reset();
  E.ReadySeconds = R.ReadySeconds;
  if (!R.Error.empty()) {
    // The interp tier renders correctly; the faster kernel is lost, and the reason reported.
    E.Error = R.Error;
    std::fprintf(stderr, "texrender: warning: the shape kernel failed to build; frames keep "
                         "the interp tier: %s\n", R.Error.substr(0, R.Error.find('\n')).c_str());
    PendingReencode = nullptr;
    return;
  }
  if (R.Shape() || !R.SameLayout)
    E.FirstFrame = int(FramesRendered); // it renders this frame (an interp-only job does not)
  try {
    adopt(R);
  } catch (const cl::Error &Ex) {
    throw Error(std::string("OpenCL call ") + Ex.what() + " failed: " + clErrorName(Ex.err()));
  }
}

void Renderer::adopt(TierBuildResult &R) {
  if (!R.SameLayout) {
    if (PendingReencode)
      PendingReencode(R.L);
    PendingReencode = nullptr;
    Lay = std::move(R.L);
    uploadLayoutData();
  }
  if (R.Interp()) {
    InterpProgram = R.Interp;
    FallbackSlots = R.FallbackSlots;
  }
  if (R.Shape())
    ShapeProgram = R.Shape;
  if (HasTextureWork)
    activate(ShapeProgram() ? ShapeProgram : InterpProgram,
             ShapeProgram() ? ShapeTierName : FallbackTierName);
}

double Renderer::waitForBackgroundBuild() {
  double T0 = steadySeconds();
  while (Pending || Queued || !Retired.empty()) {
    reapRetired(/*Wait=*/true);
    launchQueued();
    if (Pending)
      Pending->wait();
    adoptReadyBuild();
  }
  return steadySeconds() - T0;
}

} // namespace texrender
