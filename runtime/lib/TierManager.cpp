// The texture kernels of a Renderer: building them, and for shape-mode layouts the two tiers
// (TextureTiers.h): the interp fallback renders while the shape kernel builds on a background
// thread, and frames switch to the shape kernel at the first frame after it is ready.

#include "texrender/TierManager.h"
#include "texrender/Error.h"
#include "texrender/SlowStep.h"

#include <algorithm>
#include <filesystem>

#include <cstdio>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace texrender {

TierBuildPlan planTierBuilds(TierPolicy P, bool ShapeCached, bool FallbackCached) {
  const bool Auto = P == TierPolicy::Auto;
  const bool PrimaryNow = P == TierPolicy::Shape || (Auto && (ShapeCached || !FallbackCached));
  const bool FallbackNow = P == TierPolicy::Interp || (Auto && FallbackCached);
  TierBuildPlan Plan;
  for (const auto &[Role, Now] : {std::pair(ProgramRole::Primary, PrimaryNow),
                                  std::pair(ProgramRole::Fallback, FallbackNow)}) {
    if (Now)
      Plan.Now.push_back(Role);
    else if (Auto) // tiers shape and interp build nothing behind
      Plan.Later.push_back(Role);
  }
  return Plan;
}

TierManager::TierManager(ClContext &Cl, const Layout &Lay, TierPolicy Policy,
                         bool InterpStackHeadroom, std::string ProgramOptions, double Epoch,
                         std::function<bool(Layout &&)> AdoptLayout)
    : Cl(Cl), Lay(Lay), Policy(Policy), InterpStackHeadroom(InterpStackHeadroom),
      ProgramOptions(std::move(ProgramOptions)), Epoch(Epoch),
      AdoptLayout(std::move(AdoptLayout)) {}

namespace {

void warnShapeBuildFailed(const std::string &Error) {
  std::fprintf(stderr, "texrender: warning: the shape kernel failed to build; frames keep "
                       "the interp tier: %s\n", Error.substr(0, Error.find('\n')).c_str());
}

} // namespace

TierManager::~TierManager() {
  if (Running) {
    BackgroundBuild &B = *Running->Build;
    // The optimised build behind a quick first build: its binary is stored for the next run.
    std::optional<SlowStep> Step;
    if (ActiveQuickFirst && !B.ready())
      Step.emplace("finishing the optimised texture kernel for the program cache");
    // A build that failed after the last frame began was never adopted: say so now.
    B.wait();
    const TierBuildResult R = B.take();
    if (!R.Error.empty())
      warnShapeBuildFailed(R.Error);
  }
  for (auto &R : Retired)
    R->wait();
}

std::string TierManager::tierName(ProgramRole Role) const {
  switch (Role) {
  case ProgramRole::Fallback:
    return FallbackTierName;
  case ProgramRole::Quick:
    return QuickTierName;
  case ProgramRole::Primary:
    break;
  }
  return Lay.Mode;
}

const char *tierEventName(TierEvent::Kind K) {
  switch (K) {
  case TierEvent::Kind::Built:
    return "built";
  case TierEvent::Kind::Adopted:
    return "adopted";
  case TierEvent::Kind::Failed:
    return "failed";
  }
  return "built";
}

void TierManager::emit(TierEvent E) {
  for (const TierSubscriber &S : Subscribers)
    S(E);
}

void TierManager::emitForJob(TierEvent::Kind K, const TierJob &J, const BuildEvent &B) {
  TierEvent E;
  E.K = K;
  E.Background = B.Background;
  E.Switches = J.switches();
  E.Seconds = B.ReadySeconds >= 0 ? B.ReadySeconds - B.StartSeconds : 0;
  E.Reason = B.Reason;
  E.Error = B.Error;
  for (const TierProgram &P : J.Programs) {
    E.Role = P.Role;
    emit(E);
  }
}

namespace {
/// The build option of a quick first build (setQuickFirstBuild), and the line of the kernel
/// text that allows it (texcc_device.h's TEXCC_FN under #ifndef; older texcc outputs lack it).
const char *const QuickFirstOption = " -DTEXCC_FN=__attribute__((noinline))";
const char *const QuickFirstGuard = "#ifndef TEXCC_FN";
} // namespace

cl::Program TierManager::buildForeground(const std::string &Path, const std::string &Source,
                                         ProgramRole Role, const std::string &Reason,
                                         const std::string &ExtraOptions, bool QuickFirst) {
  SlowStep Step("building the texture kernel (" + std::filesystem::path(Path).filename().string() +
                (QuickFirst ? ", quick first build" : "") + ")");
  BuildEvent E;
  E.Kernel = tierName(Role) + (QuickFirst ? "-first" : "");
  E.Reason = Reason;
  E.StartSeconds = steadySeconds() - Epoch;
  // PoCL's compile at the first launch is part of the build the frame waits for.
  std::vector<std::string> Names = textureKernelNames();
  if (tierUsesUniforms(Role))
    Names.push_back(Lay.Uniforms);
  // A quick first build is not warmed up: its first frame compiles only the work-group function
  // it launches (the reduced first pass: the small-grid one), about half of warming both (rust's
  // interp kernel at load 6.6: build 231 ms, each launch's compile 596 ms; bench/coldstart.md).
  std::function<void(const cl::Program &)> WarmUp;
  if (!QuickFirst)
    WarmUp = [&](const cl::Program &Q) { warmUpKernels(Cl, Q, Names, Path); };
  cl::Program P = Cl.buildProgram(Path, Source, ProgramOptions + ExtraOptions, "", false, WarmUp);
  E.ReadySeconds = steadySeconds() - Epoch;
  E.FirstFrame = int(FramesRendered);
  Events.push_back(E);
  emit({TierEvent::Kind::Built, Role, /*Background=*/false, /*Switches=*/false, 1,
        E.ReadySeconds - E.StartSeconds, Reason, ""});
  return P;
}

bool TierManager::tierUsesUniforms(ProgramRole Role) const {
  // The layout's own kernel (shape mode's shape tier, or an interp-mode kernel that hoists);
  // shape mode's interp fallback never reads hoisted values, nor do the quick tier's node
  // kernels.
  return !Lay.Uniforms.empty() && Role == ProgramRole::Primary;
}

std::vector<std::string> TierManager::textureKernelNames() const {
  // Wavefront: every node kernel in launch order, then the outputs kernel (kernel.entry).
  std::vector<std::string> Names = Lay.WavefrontLaunches;
  Names.push_back(Lay.Entry);
  return Names;
}

double TierManager::foregroundBuildSeconds() const {
  double S = 0;
  for (const BuildEvent &E : Events)
    if (!E.Background && E.ReadySeconds >= 0)
      S += E.ReadySeconds - E.StartSeconds;
  return S;
}

void TierManager::activate(const cl::Program &P, ProgramRole Role) {
  TextureKernels.clear();
  ActiveQuickFirst = false;
  ActiveRole = Role;
  ActiveTier = tierName(Role);
  std::string File = Role == ProgramRole::Fallback ? Lay.InterpFallback : Lay.KernelSource;
  for (const std::string &N : textureKernelNames()) {
    try {
      TextureKernels.push_back(cl::Kernel(P, N.c_str()));
    } catch (const cl::Error &E) {
      throw Error(File + ": no kernel '" + N + "' in the texture program (" +
                  clErrorName(E.err()) + ")");
    }
  }
  UniformsKernel = cl::Kernel();
  UniformsDirty = true;
  if (tierUsesUniforms(Role)) {
    try {
      UniformsKernel = cl::Kernel(P, Lay.Uniforms.c_str());
    } catch (const cl::Error &E) {
      throw Error(File + ": no kernel '" + Lay.Uniforms + "' in the texture program (" +
                  clErrorName(E.err()) + ")");
    }
  }
}

void TierManager::build(bool HasWork) {
  HasTextureWork = HasWork;
  Waiting.clear();
  supersedeRunning();
  ActiveQuickFirst = false;
  TextureKernels.clear();
  Programs.clear();
  ActiveTier.clear();
  ActiveRole = ProgramRole::Primary;
  if (!HasTextureWork)
    return;
  const char *Reason = FramesRendered ? "edit" : "initial";
  if (!Lay.Caps.InterpFallback) {
    InterpModeSlots = Lay.StackSlots;
    const std::string Source = readKernelSource(Lay.KernelSource);
    std::vector<std::string> Names = textureKernelNames();
    if (tierUsesUniforms(ProgramRole::Primary))
      Names.push_back(Lay.Uniforms);
    requireKernelsDeclared(Lay.KernelSource, Source, Names);
    const std::string Headroom = Lay.Caps.StackHeadroom && InterpStackHeadroom
                                     ? stackHeadroomOption(Lay, Source, InterpModeSlots)
                                     : "";
    if (QuickFirstBuild && Source.find(QuickFirstGuard) != std::string::npos &&
        !Cl.isCached(Source, ProgramOptions + Headroom)) {
      activate(Programs[ProgramRole::Primary] =
                   buildForeground(Lay.KernelSource, Source, ProgramRole::Primary, Reason,
                                   Headroom + QuickFirstOption, /*QuickFirst=*/true),
               ProgramRole::Primary);
      ActiveQuickFirst = true;
      QuickFirstFrame = FramesRendered;
      TierJob Job{/*SameLayout=*/true, {{ProgramRole::Primary, Source, Headroom}}, /*Nice=*/0};
      hold(sameLayoutBuild(Release::Pass, Job, Reason));
      return;
    }
    activate(Programs[ProgramRole::Primary] =
                 buildForeground(Lay.KernelSource, Source, ProgramRole::Primary, Reason, Headroom),
             ProgramRole::Primary);
    return;
  }
  buildShapeTiers(Reason);
}

void TierManager::buildShapeTiers(const char *Reason) {
  const std::string ShapeText = readKernelSource(Lay.KernelSource);
  const std::string FallbackText = readKernelSource(Lay.InterpFallback);
  std::vector<std::string> ShapeNames = textureKernelNames();
  requireKernelsDeclared(Lay.InterpFallback, FallbackText, ShapeNames);
  if (tierUsesUniforms(ProgramRole::Primary))
    ShapeNames.push_back(Lay.Uniforms);
  requireKernelsDeclared(Lay.KernelSource, ShapeText, ShapeNames);
  const std::string FallbackHeadroom = stackHeadroomOption(Lay, FallbackText, FallbackSlots);
  const bool ShapeCached = Cl.isCached(ShapeText, ProgramOptions);
  const bool FallbackCached = Cl.isCached(FallbackText, ProgramOptions + FallbackHeadroom);
  const TierBuildPlan Plan = planTierBuilds(Policy, ShapeCached, FallbackCached);
  // Neither cached (a changed function): the quick tier, when it needs at most one build. The
  // shape kernel is built behind it once its first full-resolution pass is done (fullPassDone),
  // at the renderer's own priority, and takes over when it is ready; its fallback waits for
  // startDeferredBuild (setQuickTier: the caller drives both).
  if (Policy == TierPolicy::Auto && !ShapeCached && !FallbackCached && buildQuickTier(Reason)) {
    TierJob Shape{/*SameLayout=*/true, {{ProgramRole::Primary, ShapeText}}, /*Nice=*/0};
    TierJob Fallback{/*SameLayout=*/true, {{ProgramRole::Fallback, FallbackText}}};
    hold(sameLayoutBuild(Release::FullPass, Shape, Reason));
    hold(sameLayoutBuild(Release::DeferredStart, Fallback, Reason));
    return;
  }
  auto Text = [&](ProgramRole R) -> const std::string & {
    return R == ProgramRole::Primary ? ShapeText : FallbackText;
  };
  for (ProgramRole R : Plan.Now) {
    const bool Primary = R == ProgramRole::Primary;
    Programs[R] = buildForeground(Primary ? Lay.KernelSource : Lay.InterpFallback, Text(R), R,
                                  Reason, Primary ? "" : FallbackHeadroom);
  }
  activate(program(renderingRole()), renderingRole());
  if (Plan.Later.empty())
    return;
  TierJob Job{/*SameLayout=*/true, {}, backgroundBuildNice()};
  for (ProgramRole R : Plan.Later)
    Job.Programs.push_back({R, Text(R)});
  const bool Defer = DeferFallback && !Job.switches(); // a fallback built alone
  WaitingBuild B = sameLayoutBuild(Defer ? Release::DeferredStart : Release::Free, Job, Reason);
  if (Defer)
    hold(std::move(B));
  else
    startBackgroundBuild(std::move(B));
}

unsigned TierManager::quickScratchFloat4PerHit() const {
  return QuickTier ? Lay.Manifest.Kernel.QuickScratchFloat4PerHit : 0;
}

bool TierManager::buildQuickTier(const char *Reason) {
  const texcc::kernel::KernelEntries &K = Lay.Manifest.Kernel;
  const std::vector<texcc::kernel::RoleProgram> Quick = K.programs(ProgramRole::Quick);
  if (!QuickTier || FramesRendered == 0 || Quick.empty() || K.QuickEntry.empty())
    return false;
  // A warm-up still in flight is not waited for (it can take seconds, niced): without its
  // programs the edit takes the shape kernel's path, as before the quick tier.
  mergeQuickWarmUp(/*Wait=*/false);
  std::vector<std::string> Paths, Texts;
  unsigned Missing = 0;
  for (const texcc::kernel::RoleProgram &P : Quick) {
    Paths.push_back(Lay.Dir + "/" + P.Source);
    Texts.push_back(readKernelSource(Paths.back()));
    Missing += QuickKept.count(quickKey(Texts.back())) ? 0 : 1;
  }
  if (Missing > 1)
    return false;
  std::map<std::string, cl::Program> Now;
  std::map<std::string, cl::Program> ByKernel;
  for (size_t I = 0; I < Texts.size(); ++I) {
    const texcc::kernel::RoleProgram &P = Quick[I];
    auto It = QuickKept.find(quickKey(Texts[I]));
    cl::Program Prog;
    if (It != QuickKept.end()) {
      Prog = It->second;
    } else {
      requireKernelsDeclared(Paths[I], Texts[I], P.Kernels);
      BuildEvent E;
      E.Kernel = QuickTierName;
      E.Reason = Reason;
      E.StartSeconds = steadySeconds() - Epoch;
      // PoCL's compile belongs to the build
      Prog = Cl.buildProgram(Paths[I], Texts[I], ProgramOptions, "", false,
                             [&](const cl::Program &Q) { warmUpKernels(Cl, Q, P.Kernels, Paths[I]); });
      E.ReadySeconds = steadySeconds() - Epoch;
      E.FirstFrame = int(FramesRendered);
      Events.push_back(E);
      emit({TierEvent::Kind::Built, ProgramRole::Quick, /*Background=*/false,
            /*Switches=*/false, 1, E.ReadySeconds - E.StartSeconds, Reason, ""});
    }
    Now[quickKey(Texts[I])] = Prog;
    for (const std::string &Name : P.Kernels)
      ByKernel[Name] = Prog;
  }
  QuickKept = std::move(Now); // only this layout's programs are kept
  std::vector<std::string> Names;
  for (const texcc::kernel::LaunchLayout &L : K.QuickLaunches)
    Names.push_back(L.Kernel);
  Names.push_back(K.QuickEntry);
  TextureKernels.clear();
  for (const std::string &N : Names) {
    auto It = ByKernel.find(N);
    if (It == ByKernel.end())
      throw Error(Lay.Dir + "/layout.json: /kernel/quick: no program holds kernel '" + N + "'");
    TextureKernels.push_back(cl::Kernel(It->second, N.c_str()));
  }
  ActiveRole = ProgramRole::Quick;
  ActiveTier = tierName(ProgramRole::Quick);
  UniformsKernel = cl::Kernel(); // node kernels call the functions unhoisted
  UniformsDirty = true;
  return true;
}

bool TierManager::warmQuickPrograms() {
  const std::vector<texcc::kernel::RoleProgram> Quick =
      Lay.Manifest.Kernel.programs(ProgramRole::Quick);
  if (!QuickTier || !HasTextureWork || Quick.empty())
    return false;
  mergeQuickWarmUp(false);
  if (QuickWarming.valid())
    return false;
  struct Todo {
    std::string Path, Source;
    std::vector<std::string> Kernels;
  };
  std::vector<Todo> Work;
  for (const texcc::kernel::RoleProgram &P : Quick) {
    Todo T{Lay.Dir + "/" + P.Source, readKernelSource(Lay.Dir + "/" + P.Source), P.Kernels};
    if (!QuickKept.count(quickKey(T.Source)))
      Work.push_back(std::move(T));
  }
  if (Work.empty())
    return false;
  ClContext *Ctx = &Cl;
  const std::string Options = ProgramOptions;
  const double Start = Epoch;
  QuickWarmingEnded = std::make_shared<std::atomic<bool>>(false);
  QuickWarming = std::async(std::launch::async, [Ctx, Work, Options, Start, W = Wake,
                                                 Ended = QuickWarmingEnded] {
    lowerThisThreadsPriority(backgroundBuildNice()); // as BackgroundBuild's thread
    std::vector<QuickWarmed> Out;
    for (const Todo &T : Work) {
      QuickWarmed Q;
      Q.Source = T.Source;
      Q.StartSeconds = steadySeconds() - Start;
      try {
        waitForEditPause(); // PoCL's compiler holds up launches while it runs
        Q.Program = Ctx->buildProgram(T.Path, T.Source, Options, "", /*Background=*/true,
                                      [&](const cl::Program &P) {
                                        warmUpKernels(*Ctx, P, T.Kernels, T.Path, true);
                                      });
      } catch (const std::exception &E) {
        Q.Program = cl::Program();
        Q.Error = E.what();
      }
      Q.ReadySeconds = steadySeconds() - Start;
      Out.push_back(std::move(Q));
    }
    // The future is ready only once this returns: mergeQuickWarmUp waits for it when Ended.
    Ended->store(true);
    if (W)
      W();
    return Out;
  });
  return true;
}

void TierManager::mergeQuickWarmUp(bool Wait) {
  if (!QuickWarming.valid())
    return;
  if (!Wait && !QuickWarmingEnded->load() &&
      QuickWarming.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  std::vector<QuickWarmed> Done = QuickWarming.get();
  unsigned Built = 0;
  for (QuickWarmed &W : Done) {
    BuildEvent E;
    E.Kernel = QuickTierName;
    E.Reason = "warm-up";
    E.Background = true;
    E.StartSeconds = W.StartSeconds;
    E.ReadySeconds = W.ReadySeconds;
    E.Error = W.Error;
    Events.push_back(E);
    if (W.Error.empty()) {
      QuickKept[quickKey(W.Source)] = W.Program;
      ++Built;
    } else {
      emit({TierEvent::Kind::Failed, ProgramRole::Quick, true, false, 1,
            W.ReadySeconds - W.StartSeconds, E.Reason, W.Error});
    }
  }
  if (Built)
    emit({TierEvent::Kind::Built, ProgramRole::Quick, true, false, Built,
          Done.back().ReadySeconds - Done.front().StartSeconds, "warm-up", ""});
}

TierManager::WaitingBuild TierManager::sameLayoutBuild(Release When, TierJob Job,
                                                       const char *Reason) const {
  return WaitingBuild{When, std::move(Job), [Same = Lay] { return Same; }, nullptr, Reason};
}

void TierManager::hold(WaitingBuild B) {
  for (WaitingBuild &W : Waiting)
    if (W.When == B.When) {
      W = std::move(B);
      return;
    }
  Waiting.push_back(std::move(B));
}

const TierManager::WaitingBuild *TierManager::waitingFor(Release When) const {
  for (const WaitingBuild &W : Waiting)
    if (W.When == When)
      return &W;
  return nullptr;
}

bool TierManager::release(Release When) {
  for (auto It = Waiting.begin(); It != Waiting.end(); ++It)
    if (It->When == When) {
      WaitingBuild B = std::move(*It);
      Waiting.erase(It);
      startBackgroundBuild(std::move(B));
      return true;
    }
  return false;
}

bool TierManager::switchPending() const {
  // A fallback built alone (the deferred build) switches nothing.
  for (const WaitingBuild &W : Waiting)
    if (W.Job.switches())
      return true;
  return Running && Running->Job.switches() && !Running->Announced;
}

void TierManager::passDone() {
  release(Release::Pass);
  // A layout without a fallback has no other background build than this one.
  if (ActiveQuickFirst && Running && Running->Build->ready())
    adoptReadyBuild();
}

bool TierManager::fullPassDone() {
  release(Release::Pass); // not the shape kernel's build: the caller says nothing about it
  return release(Release::FullPass);
}

bool TierManager::startDeferredBuild() {
  if (Running || waitingFor(Release::Free) || waitingFor(Release::FullPass))
    return false;
  return release(Release::DeferredStart);
}

void TierManager::switchShapes(bool HasWork, std::function<Layout()> MakeLayout,
                               std::function<void(Layout &)> Reencode) {
  if (!canSwitchShapes())
    throw Error("switchShapes: needs a shape-mode layout with its interp fallback built (tier auto)");
  HasTextureWork = HasWork;
  if (HasTextureWork && ActiveRole != ProgramRole::Fallback)
    activate(program(ProgramRole::Fallback), ProgramRole::Fallback);
  TierJob Job{/*SameLayout=*/false, {{ProgramRole::Primary}, {ProgramRole::Fallback}},
              backgroundBuildNice()};
  startBackgroundBuild(WaitingBuild{Release::Free, std::move(Job), std::move(MakeLayout),
                                    std::move(Reencode), "shape change"});
}

void TierManager::startBackgroundBuild(WaitingBuild B) {
  supersedeRunning();
  B.When = Release::Free;
  hold(std::move(B));
  launchFree();
}

void TierManager::launchFree() {
  // One build thread at a time: a superseded build cannot be cancelled, and letting it finish
  // before the next one starts keeps rapid edits from piling up builds on the same cores.
  reapRetired(false);
  if (Running || !Retired.empty())
    return;
  auto It = std::find_if(Waiting.begin(), Waiting.end(),
                         [](const WaitingBuild &W) { return W.When == Release::Free; });
  if (It == Waiting.end())
    return;
  WaitingBuild B = std::move(*It);
  Waiting.erase(It);
  BuildEvent E;
  E.Kernel = tierName(B.Job.Programs.front().Role);
  E.Reason = B.Reason;
  E.Background = true;
  E.StartSeconds = steadySeconds() - Epoch;
  Events.push_back(E);
  ClContext *Ctx = &Cl;
  std::string Options = ProgramOptions;
  double Start = Epoch;
  auto Build = std::make_unique<BackgroundBuild>(
      [Ctx, MakeLayout = std::move(B.MakeLayout), Job = B.Job, Options, Start] {
        return buildTierJob(*Ctx, MakeLayout, Job, Options, Start);
      },
      Events.size() - 1, B.Job.Nice, Wake);
  Running = RunningBuild{std::move(Build), std::move(B.Job), std::move(B.Reencode)};
}

void TierManager::supersedeRunning() {
  Waiting.erase(std::remove_if(Waiting.begin(), Waiting.end(),
                               [](const WaitingBuild &W) { return W.When == Release::Free; }),
                Waiting.end());
  if (!Running)
    return;
  Events[Running->Build->eventIndex()].Superseded = true;
  Retired.push_back(std::move(Running->Build));
  Running.reset();
}

void TierManager::reapRetired(bool Wait) {
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

const std::string &TierManager::beginFrame() {
  // The optimised build behind a quick first build starts once two frames of the quick build
  // are complete: the first compiled the work-group function it launched (a watch session's
  // reduced first pass: the small-grid one), the second the other (the first full-resolution
  // pass). Started earlier, its compile holds up those launches (PoCL compiles one at a time):
  // rust's first image after a save waited 4-7 s for it (bench/coldstart.md).
  if (FramesRendered >= QuickFirstFrame + 2)
    release(Release::Pass);
  adoptReadyBuild(); // a background shape build that finished since the last frame
  ++FramesRendered;
  return ActiveTier;
}

void TierManager::collect(bool Rest) {
  mergeQuickWarmUp(/*Wait=*/false);
  announceReadyBuild();
  // An interp fallback built alone: adopted at rest, not at the next frame (an idle session
  // renders none, and a rewiring to a new shape needs it).
  if (Rest && Running && !Running->Job.switches() && Running->Announced)
    adoptReadyBuild();
}

void TierManager::announceReadyBuild() {
  launchFree();
  if (!Running || Running->Announced || !Running->Build->ready())
    return;
  Running->Announced = true;
  const TierBuildResult &R = Running->Build->result();
  BuildEvent &E = Events[Running->Build->eventIndex()];
  E.ReadySeconds = R.ReadySeconds;
  if (R.Error.empty()) {
    emitForJob(TierEvent::Kind::Built, Running->Job, E);
    return;
  }
  // The kernel that renders renders correctly; the faster one is lost, and the reason reported.
  E.Error = R.Error;
  warnShapeBuildFailed(R.Error);
  const TierJob Job = std::move(Running->Job);
  Running.reset();
  emitForJob(TierEvent::Kind::Failed, Job, E);
}

void TierManager::adoptReadyBuild() {
  announceReadyBuild();
  if (!Running || !Running->Announced)
    return;
  RunningBuild Done = std::move(*Running);
  Running.reset();
  TierBuildResult R = Done.Build->take();
  const size_t Index = Done.Build->eventIndex();
  if (Done.Job.switches())
    Events[Index].FirstFrame = int(FramesRendered); // it renders this frame (a fallback built
                                                    // alone does not)
  try {
    adopt(R, Done.Reencode);
  } catch (const cl::Error &Ex) {
    throw Error(std::string("OpenCL call ") + Ex.what() + " failed: " + clErrorName(Ex.err()));
  }
  emitForJob(TierEvent::Kind::Adopted, Done.Job, Events[Index]);
}

void TierManager::adopt(TierBuildResult &R, const std::function<void(Layout &)> &Reencode) {
  if (!R.SameLayout) {
    if (Reencode)
      Reencode(R.L);
    HasTextureWork = AdoptLayout(std::move(R.L));
  }
  for (const auto &[Role, P] : R.Programs)
    Programs[Role] = P;
  if (R.Programs.count(ProgramRole::Fallback))
    FallbackSlots = R.FallbackSlots;
  if (HasTextureWork)
    activate(program(renderingRole()), renderingRole());
}

double TierManager::waitForBackgroundBuild() {
  double T0 = steadySeconds();
  mergeQuickWarmUp(/*Wait=*/true);
  fullPassDone(); // a shape kernel held behind the quick tier: it is what is waited for
  while (Running || waitingFor(Release::Free) || !Retired.empty()) {
    reapRetired(/*Wait=*/true);
    launchFree();
    if (Running)
      Running->Build->wait();
    adoptReadyBuild();
  }
  return steadySeconds() - T0;
}

} // namespace texrender
