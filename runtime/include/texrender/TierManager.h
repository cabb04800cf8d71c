#ifndef TEXRENDER_TIERMANAGER_H
#define TEXRENDER_TIERMANAGER_H

// The texture kernels of a Renderer (docs/runtime.md, "Tiers"): the layout's programs by role
// (primary, fallback, quick: texcc/Kernel/Manifest.h), which one renders the next frame, the
// foreground builds frames wait for, the background builds (one thread at a time, superseded
// ones finished and dropped), their adoption at a frame or pass boundary (the interp fallback
// alone: at the first boundary at rest, collect), the events its subscribers hear (built,
// adopted, failed: TierEvent) and the build records stats.json reports. The Renderer keeps
// path tracing and launches the kernels this class hands it; the building blocks
// (BackgroundBuild, buildTierJob, the value-stack headroom) are in TextureTiers.h.

#include "texrender/ClContext.h"
#include "texrender/Layout.h"
#include "texrender/TextureTiers.h"

#include <algorithm>
#include <atomic>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace texrender {

/// Which programs of a shape-mode layout (Caps.InterpFallback) a build of its texture kernel
/// makes before the next frame (Now) and which it leaves to the background thread (Later), by
/// role (Primary: the shape kernel, Fallback: its interp fallback), the primary first.
/// Something must render the next frame, and a cached program is a load, not a build: tier
/// auto builds now what is cached, or the shape kernel when neither is (on PoCL it builds faster
/// than the fallback, whose switch holds every function), and the other behind it. Tiers shape
/// and interp build only their own program, now. The first frame renders with the shape kernel
/// when it is built now, else with the fallback.
struct TierBuildPlan {
  std::vector<ProgramRole> Now, Later;
  bool now(ProgramRole R) const { return std::count(Now.begin(), Now.end(), R) != 0; }
  bool later(ProgramRole R) const { return std::count(Later.begin(), Later.end(), R) != 0; }
};
TierBuildPlan planTierBuilds(TierPolicy P, bool ShapeCached, bool FallbackCached);

/// The quick tier's name (stats.json, the frame log).
constexpr const char *QuickTierName = "quick";

/// What the tier manager tells its subscribers (subscribe) about a program of a role: Built
/// once a build has ended (a background build: held for adoption, a quick warm-up: its
/// programs kept), Adopted once the program is the manager's (frames render with it, or for an
/// interp fallback built alone: a rewiring to a new shape can render with it at once), Failed
/// when a build failed (the kernel that renders keeps rendering). Delivered on the thread that
/// calls the manager (the render thread), from the call that saw it happen.
struct TierEvent {
  enum class Kind { Built, Adopted, Failed };
  Kind K = Kind::Built;
  ProgramRole Role = ProgramRole::Primary;
  bool Background = false; // a background build (or warm-up); else one a frame waited for
  /// Frames switch to what the build made (a new primary, or a new layout): the next frame
  /// or pass adopts it. An interp fallback built alone never switches.
  bool Switches = false;
  unsigned Programs = 1;   // quick warm-up: the programs it built
  double Seconds = 0;      // the build's wall seconds (start to end; a warm-up: first to last)
  std::string Reason;      // why it was built: "initial", "edit", "shape change", "warm-up"
  std::string Error;       // Failed: the build's error
};
const char *tierEventName(TierEvent::Kind K); // "built", "adopted", "failed"
using TierSubscriber = std::function<void(const TierEvent &)>;

class TierManager {
public:
  /// Lay: the layout the renderer runs (the renderer's own, which outlives this manager; a
  /// background build for a new layout replaces it through AdoptLayout, which returns whether
  /// the new layout has texture work). ProgramOptions: the build options of every texture
  /// program. Epoch: steadySeconds() at the renderer's creation (build-event times).
  TierManager(ClContext &Cl, const Layout &Lay, TierPolicy Policy, bool InterpStackHeadroom,
              std::string ProgramOptions, double Epoch,
              std::function<bool(Layout &&)> AdoptLayout);
  /// Waits for background builds (their results are dropped).
  ~TierManager();
  TierManager(const TierManager &) = delete;
  TierManager &operator=(const TierManager &) = delete;

  /// (Re)builds the texture kernel of the renderer's layout (its first one, or a regenerated
  /// one): supersedes a background build in flight, builds what the next frame needs in the
  /// foreground and, tier auto, the other tier on the background thread. HasTextureWork false:
  /// no texture kernel at all.
  void build(bool HasTextureWork);
  /// Whether switchShapes can run: a shape-mode layout whose interp fallback is built and
  /// adopted (a fallback finished on the background thread counts once collect, or a frame,
  /// has adopted it). No side effect.
  bool canSwitchShapes() const {
    return Lay.Caps.InterpFallback && program(ProgramRole::Fallback)();
  }
  /// Renderer::switchShapes: the interp fallback renders at once, MakeLayout's layout is built
  /// on the background thread and Reencode fills it at adoption (TextureTiers.h). The renderer
  /// has uploaded the re-encoded arguments before.
  void switchShapes(bool HasTextureWork, std::function<Layout()> MakeLayout,
                    std::function<void(Layout &)> Reencode);
  /// At a frame's start: adopts a background build that finished since the last frame, counts
  /// the frame and returns the tier it renders with ("" without texture work).
  const std::string &beginFrame();
  /// Waits for the background build in flight, if any, and switches to its kernels. Returns
  /// the seconds waited.
  double waitForBackgroundBuild();
  /// Events (TierEvent) go to every subscriber, in the order they happen. texrender --watch's
  /// session subscribes to learn of finished builds and to print them.
  void subscribe(TierSubscriber S) { Subscribers.push_back(std::move(S)); }
  /// Called on the build's own thread as each background build or quick warm-up ends (the
  /// session's wake-up: it then calls collect at its next boundary). Must be thread-safe.
  void setWake(std::function<void()> W) { Wake = std::move(W); }
  /// Takes the background builds that ended since the last call: Built or Failed for each (a
  /// failed one is dropped; a quick warm-up's programs are kept), and starts a build queued
  /// behind a superseded one that has ended. Rest: the caller is between frames (idle, or about
  /// to plan an edit), so a finished interp fallback built alone is adopted now (Adopted; the
  /// layout's own kernel renders on, and a rewiring to a new shape needs it); else (between the
  /// stages of a pass) nothing is adopted. A build that frames switch to is adopted by the
  /// next frame or pass (beginFrame, passDone), as ever.
  void collect(bool Rest);
  /// A background build that makes a kernel to switch to (the shape kernel, or a new layout)
  /// is queued, held or running and has not ended. No side effect.
  bool switchPending() const;
  /// On: a background build that makes only the interp fallback of a layout whose own kernel
  /// renders (tier auto: the shape kernel built in the foreground, or built behind the quick
  /// tier) waits for startDeferredBuild() instead of starting with the layout. texrender
  /// --watch starts it once the frame is complete: built at once, its compile competes for the
  /// cores (and PoCL's device) with the first frames of new code (docs/live.md).
  void setDeferFallbackBuilds(bool On) { DeferFallback = On; }
  /// Starts the deferred build, if there is one and no other build is pending; returns whether
  /// it started.
  bool startDeferredBuild();

  /// On (texrender --watch): shape mode's quick tier (layout.json kernel.quick, docs/live.md).
  /// warmQuickPrograms() builds the layout's quick programs on a thread of their own and keeps
  /// them; a regenerated layout whose shape kernel and fallback are both uncached then renders
  /// with its quick programs when all but at most one are kept (a saved source file that changed
  /// one function): that one is built in the foreground, tier "quick", the shape kernel is built
  /// behind it once the quick tier's first full-resolution pass is done (the caller calls
  /// fullPassDone; started at the adoption, its compile slowed that pass, bench/lookdev.md), at
  /// the renderer's own priority (TierJob::Nice 0: at nice 19 it waited a minute behind a loaded
  /// machine), and takes over when it is ready; its fallback waits for startDeferredBuild
  /// (whether or not setDeferFallbackBuilds is on). A save while the warm-up runs does not wait
  /// for it: the shape kernel's path, as without the quick tier.
  void setQuickTier(bool On) { QuickTier = On; }
  /// A full-resolution pass is done (texrender --watch, after each): starts the shape kernel's
  /// build held behind the quick tier, if there is one; returns whether it started. It also
  /// starts the optimised build held behind a quick first build (not counted in the result).
  bool fullPassDone();
  /// The quick first build (on by default; $TEXRENDER_FIRST_BUILD=optimised turns it off): a
  /// layout's own kernel (interp, inline, wavefront mode) whose optimised program is not in the
  /// program cache is built first with TEXCC_FN noinline (texcc_device.h; the kernel's text is
  /// unchanged, the option is -DTEXCC_FN=...): PoCL compiles each function once and vectorises
  /// nothing, several times faster to build, slower per hit, the same values bit for bit. It is
  /// not warmed up (its first launches compile what they use). The optimised program (the same
  /// text, inlined) is built on the background thread after a pass of a frame (passDone), a
  /// full-resolution pass (fullPassDone) or two complete frames, and takes over at the next
  /// pass or frame; its binary goes to the cache, so the next run loads it.
  void setQuickFirstBuild(bool On) { QuickFirstBuild = On; }
  /// Between two passes of a frame (Renderer::render): starts the optimised build held behind a
  /// quick first build and adopts it once it is done (the same values: the frame goes on).
  void passDone();
  /// Whether the kernel that renders is a quick first build.
  bool quickFirstBuildActive() const { return ActiveQuickFirst; }
  /// Starts building, in the background, the quick programs of the layout not kept yet (none
  /// while an earlier warm-up runs); returns whether it started.
  bool warmQuickPrograms();
  /// The node values per hit the quick tier needs in the texture scratch buffer (0 when off).
  unsigned quickScratchFloat4PerHit() const;
  /// The active tier's texture kernels in launch order (one, or wavefront's node launches and
  /// its outputs kernel).
  std::vector<cl::Kernel> &kernels() { return TextureKernels; }
  /// The active tier's texcc_uniforms when fakeStack (or the kernel) changed since it last
  /// ran, else nullptr; the caller launches it and calls uniformsRan().
  cl::Kernel *uniformsDue() { return UniformsKernel() && UniformsDirty ? &UniformsKernel : nullptr; }
  void uniformsRan() { UniformsDirty = false; }
  /// fakeStack was uploaded again: texcc_uniforms runs before the next texture launch.
  void argumentsChanged() { UniformsDirty = true; }

  TierPolicy policy() const { return Policy; }
  const std::string &activeTier() const { return ActiveTier; }
  /// The value-stack slots the adopted interp fallback holds (stackHeadroomOption); 0: none
  /// (also while it is built on the background thread and not adopted). No side effect.
  unsigned fallbackStackSlots() const {
    return program(ProgramRole::Fallback)() ? FallbackSlots : 0;
  }
  /// interp mode: the value-stack slots the built kernel holds.
  unsigned interpStackSlots() const { return InterpModeSlots; }
  /// Every texture-kernel build so far, foreground and background (stats.json textureBuilds).
  const std::vector<BuildEvent> &buildEvents() const { return Events; }
  /// Wall seconds of the texture-kernel builds (and cache loads) frames waited for, so far.
  double foregroundBuildSeconds() const;

  /// The layout's built program of role R (Primary or Fallback; the quick tier's are kept per
  /// function), or a null program.
  cl::Program program(ProgramRole R) const {
    auto It = Programs.find(R);
    return It == Programs.end() ? cl::Program() : It->second;
  }

private:
  /// What releases a background build that waits (Waiting).
  enum class Release {
    Free,          // no build running or retired: the newest request, behind a superseded one
    DeferredStart, // startDeferredBuild: a fallback built alone (setDeferFallbackBuilds, and
                   // the quick tier's fallback)
    FullPass,      // fullPassDone: the shape kernel behind the quick tier
    Pass,          // passDone, fullPassDone or beginFrame's second frame after a quick first
                   // build: the optimised build behind it
  };
  /// A background build that waits for its release.
  struct WaitingBuild {
    Release When = Release::Free;
    TierJob Job;
    std::function<Layout()> MakeLayout;
    std::function<void(Layout &)> Reencode; // fills a new layout's args.bin at adoption
    std::string Reason;
  };
  /// The background build in flight.
  struct RunningBuild {
    std::unique_ptr<BackgroundBuild> Build;
    TierJob Job;
    std::function<void(Layout &)> Reencode;
    bool Announced = false; // it has ended and Built was emitted (announceReadyBuild)
  };

  void emit(TierEvent E);
  /// emit for each role Job builds (Primary, Fallback).
  void emitForJob(TierEvent::Kind K, const TierJob &J, const BuildEvent &B);
  /// A build of the renderer's layout that waits for When.
  WaitingBuild sameLayoutBuild(Release When, TierJob Job, const char *Reason) const;
  /// Queues B, replacing the build that waits for the same release, if any.
  void hold(WaitingBuild B);
  /// The build that waits for When, or nullptr. No side effect.
  const WaitingBuild *waitingFor(Release When) const;
  /// Starts the build that waits for When, if any; returns whether there was one.
  bool release(Release When);
  /// The background build in flight, if it has ended: Built (or Failed: then dropped), once.
  void announceReadyBuild();
  void buildShapeTiers(const char *Reason);
  /// The quick tier for this layout, if its programs are kept but at most one (built here).
  bool buildQuickTier(const char *Reason);
  void mergeQuickWarmUp(bool Wait);
  static std::string quickKey(const std::string &Source) { return Source; }
  /// ExtraOptions: appended to ProgramOptions (the value-stack headroom's -D).
  /// Role: Fallback, the layout's interp fallback (Caps.InterpFallback), or Primary, the
  /// layout's own kernel.
  cl::Program buildForeground(const std::string &Path, const std::string &Source, ProgramRole Role,
                              const std::string &Reason, const std::string &ExtraOptions = "",
                              bool QuickFirst = false);
  void activate(const cl::Program &P, ProgramRole Role);
  bool tierUsesUniforms(ProgramRole Role) const;
  /// The tier's name in stats.json and the frame log: the fallback's FallbackTierName, the
  /// quick tier's QuickTierName, else the layout's mode as its manifest names it (a label only:
  /// nothing compares it).
  std::string tierName(ProgramRole Role) const;
  /// The primary if built, else the fallback.
  ProgramRole renderingRole() const {
    return program(ProgramRole::Primary)() ? ProgramRole::Primary : ProgramRole::Fallback;
  }
  std::vector<std::string> textureKernelNames() const;
  /// Supersedes the build in flight and the one waiting behind it; B starts once the
  /// superseded builds have ended.
  void startBackgroundBuild(WaitingBuild B);
  void supersedeRunning();
  /// Starts the build released by Free once no build runs or is retired.
  void launchFree();
  void reapRetired(bool Wait);
  void adoptReadyBuild();
  void adopt(TierBuildResult &R, const std::function<void(Layout &)> &Reencode);

  ClContext &Cl;
  const Layout &Lay;
  const TierPolicy Policy;
  const bool InterpStackHeadroom;
  const std::string ProgramOptions;
  const double Epoch;
  std::function<bool(Layout &&)> AdoptLayout;
  bool HasTextureWork = false;

  std::string ActiveTier; // tierName(ActiveRole); "" without texture work
  // The role of the program that renders (Quick: kernels of QuickKept's programs).
  ProgramRole ActiveRole = ProgramRole::Primary;
  std::vector<cl::Kernel> TextureKernels;
  // The texcc_uniforms of the shape tier or of an interp kernel that hoists (Layout::Uniforms),
  // and whether fakeStack changed (or the kernel did) since it last ran.
  cl::Kernel UniformsKernel;
  bool UniformsDirty = true;
  // The layout's programs by role (Primary, Fallback) once built and adopted.
  std::map<ProgramRole, cl::Program> Programs;
  unsigned FallbackSlots = 0;
  unsigned InterpModeSlots = 0;
  // The background builds: the one in flight, the superseded ones still running (a build
  // cannot be cancelled: the next one starts once they have ended) and those waiting for their
  // release, at most one per Release.
  std::optional<RunningBuild> Running;
  std::vector<std::unique_ptr<BackgroundBuild>> Retired;
  std::vector<WaitingBuild> Waiting;
  bool DeferFallback = false;
  bool QuickFirstBuild = true;
  bool ActiveQuickFirst = false; // the kernel that renders is a quick first build
  unsigned QuickFirstFrame = 0;  // FramesRendered when it was built
  std::vector<BuildEvent> Events;
  unsigned FramesRendered = 0;
  bool QuickTier = false;
  // Quick programs built and warmed up, by source text (those of the current layout).
  std::map<std::string, cl::Program> QuickKept;
  struct QuickWarmed {
    std::string Source;
    cl::Program Program;
    double StartSeconds = 0, ReadySeconds = 0;
    std::string Error;
  };
  std::future<std::vector<QuickWarmed>> QuickWarming;
  // Set by the warm-up's thread as it returns (its wake-up may come before the future is ready).
  std::shared_ptr<std::atomic<bool>> QuickWarmingEnded;
  std::vector<TierSubscriber> Subscribers;
  std::function<void()> Wake;
};

} // namespace texrender

#endif
