#ifndef TEXRENDER_TEXTURETIERS_H
#define TEXRENDER_TEXTURETIERS_H

// Tiered texture execution for shape-mode outputs (docs/runtime.md, "Tiers"). A shape-mode
// folder holds two kernels of one graph that run the same args.bin: the shape kernel
// (proctex.cl, straight-line code per graph shape: fast per hit, but one build per new shape)
// and its interp fallback (proctex.interp.cl: depends only on the set of functions, so it
// survives rewirings). While the shape kernel is not built, frames render with the interp
// tier and the shape kernel builds on a background thread; frames switch once it is ready.

#include "texrender/ClContext.h"
#include "texrender/Layout.h"

#include <functional>
#include <future>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace texrender {

/// --tier: auto = tiered (interp while the shape kernel builds in the background); interp =
/// the fallback kernel only (never builds a shape kernel); shape = the shape kernel only, and
/// a frame waits for its build (the behaviour before tiers).
enum class TierPolicy { Auto, Interp, Shape };

/// The tiers of a layout with an interp fallback (Layout::Caps.InterpFallback), as --tier
/// spells its policies and stats.json names the tiers: the layout's kernel and its interp
/// fallback. Labels only: the tier manager tracks which program renders by its role, and names
/// the layout's own kernel by the manifest's mode ("shape" for such a layout), never comparing
/// either name.
constexpr const char *ShapeTierName = "shape";
constexpr const char *FallbackTierName = "interp";

/// Parses "auto" | "interp" | "shape"; throws Error naming the allowed values.
TierPolicy parseTierPolicy(const std::string &Name);
const char *tierPolicyName(TierPolicy P);

/// One texture-kernel program built (or loaded from the program cache) for the renderer.
struct BuildEvent {
  std::string Kernel;        // the tier it serves: "shape", "interp", "inline", "wavefront"
  std::string Reason;        // "initial", "edit" (a regenerated kernel), "shape change"
  bool Background = false;   // built on the background thread (no frame waited for it)
  double StartSeconds = 0;   // since the renderer was created
  double ReadySeconds = -1;  // -1: not finished when stats were written
  int FirstFrame = -1;       // the first frame it rendered (-1: none)
  bool Superseded = false;   // a later edit made it stale before it was used
  std::string Error;         // a failed background build: the interp tier kept rendering
};

/// A program's role in its layout (texcc/Kernel/Manifest.h): the layout's own kernel
/// (Primary: shape mode's shape kernel), its interp fallback (Fallback), the quick tier's.
using texcc::kernel::ProgramRole;

/// What a background job produced.
struct TierBuildResult {
  Layout L;                  // the layout the programs belong to
  bool SameLayout = false;   // L is the layout the renderer runs
  // The programs of L the job built, by role: Primary (L's own kernel: the shape kernel),
  // Fallback (its interp fallback).
  std::map<ProgramRole, cl::Program> Programs;
  unsigned FallbackSlots = 0; // the fallback's value-stack capacity (stackHeadroomOption)
  double ReadySeconds = 0;
  std::string Error;
};

/// The build option that gives an interpreter (Source, of layout L) value-stack headroom:
/// TEXCC_STACK_SLOTS is the exact peak of the graph it was made from, and a rewiring that needs
/// one or two slots more would otherwise need a new kernel (and a frame waiting for its build).
/// The capacity, max(2 N, N + 4) capped at the stack limit, goes to Capacity and the result is
/// " -DTEXCC_STACK_SLOTS=<Capacity>" (the kernel's own #define is under #ifndef; the source is
/// never edited). A spilling layout keeps its N (the spill buffer is sized by it), and so does a
/// kernel from a texcc before the #ifndef: then the result is "".
std::string stackHeadroomOption(const Layout &L, const std::string &Source, unsigned &Capacity);

/// How much lower than the thread that starts them background builds run: a nice increment,
/// 0 by default (the renderer's own priority). Frames render about 1.28x slower while a build
/// runs beside them at +0 (1.13x at +5, 0.92x at +19), but any positive increment lets every
/// nice-0 process of the machine go first: beside `stress-ng --cpu 2` a cold tier test took
/// 31-34 s at +0, 44-57 s at +2 and +5, 67 s at +19 (3.4 s alone; at load 15-19 a fallback
/// build took 33-39 s at +0 and 398 s at +19: bench/test-suite.md, session 13).
/// $TEXRENDER_BUILD_NICE (0-19) sets another increment.
constexpr int DefaultBackgroundBuildNice = 0;
int backgroundBuildNice();
/// Raises the calling thread's nice value by Increment over the one it started with (inherited
/// from the thread that created it; capped at 19; Linux: a thread's nice value is its own).
/// Increment 0: nothing.
void lowerThisThreadsPriority(int Increment);

/// One program a background job builds.
struct TierProgram {
  TierProgram(ProgramRole Role, std::string Text = "", std::string Options = "")
      : Role(Role), Text(std::move(Text)), Options(std::move(Options)) {}
  ProgramRole Role; // Primary (the layout's own kernel) or Fallback
  // Its text when read already (non-empty; else the layout's file is read): a live edit's
  // regenerated layout lives in a temporary folder that is gone by the time a deferred build
  // runs.
  std::string Text;
  // Extra build options: an interp-mode primary's value-stack headroom. A fallback's headroom
  // comes from its text as it builds (stackHeadroomOption).
  std::string Options;
};

/// What a background job builds: programs by role, the primary first (a build event names the
/// first).
struct TierJob {
  bool SameLayout = false; // for the layout the renderer runs, else for MakeLayout's new one
  std::vector<TierProgram> Programs;
  // The build thread's nice increment: backgroundBuildNice(), or 0 for the shape kernel that
  // takes over from the quick tier (TierManager::buildShapeTiers: at nice 19 it waited a
  // minute behind a loaded machine) and for the optimised build behind a quick first build.
  int Nice = backgroundBuildNice();

  bool builds(ProgramRole R) const {
    for (const TierProgram &P : Programs)
      if (P.Role == R)
        return true;
    return false;
  }
  /// Frames switch to what it makes: a new primary, or a new layout (an interp fallback of the
  /// layout that renders, built alone, never switches).
  bool switches() const { return builds(ProgramRole::Primary) || !SameLayout; }
};

/// Builds the programs Job names, in its order, for the layout MakeLayout gives (run first, on
/// the calling thread: e.g. texcc regenerating a rewired graph), then launches each once over
/// an empty range on a private queue: PoCL compiles the work-group function at the first
/// launch, and that compile belongs to the build, not to the first frame that uses it. Never
/// throws: a failure (a quick program among them included) is returned in Error.
TierBuildResult buildTierJob(ClContext &Cl, const std::function<Layout()> &MakeLayout,
                             TierJob Job, const std::string &Options, double Epoch);

/// Launches each of Kernels of P once over one work-group whose items all return at once
/// (numHits 0), on a private queue, so that PoCL's compile at the first launch happens here,
/// and the texture kernels also once over LargeGridItems work-items (PoCL compiles another
/// work-group function for grids that large: bench/lookdev.md), which a frame's first
/// full-resolution launch would otherwise compile on the render thread. Background (a
/// background build's warm-up): each launch first waits for a pause in interactive edits
/// (waitForEditPause). A kernel the program lacks: Error "File: no kernel 'NAME' in the
/// texture program". ClContext::buildProgram stores a program's binary after this, so a
/// program loaded from the cache compiles nothing here.
void warmUpKernels(ClContext &Cl, const cl::Program &P, const std::vector<std::string> &Kernels,
                   const std::string &File, bool Background = false);

/// PoCL compiles a kernel's work-group function at its first launch, and while it does every
/// launch on the device waits (an edit's first frame waited 0.2-1.7 s behind a background
/// build's warm-up; bench/lookdev.md). texrender --watch calls noteInteractiveEdit() for every
/// edit it applies; waitForEditPause() returns once none has come for EditPauseSeconds (at
/// once when there never was one), so that background compiles wait while a slider is dragged.
constexpr double EditPauseSeconds = 0.5;
void noteInteractiveEdit();
void waitForEditPause();

/// Checks, before any build, that Source (the text of File) declares each of Kernels as
/// `kernel void NAME(` (with or without the `__`): a layout.json naming a kernel the program
/// lacks is an Error "File: no kernel 'NAME' in the texture program" at once, whichever tier
/// would build first (a tier built in the background would otherwise only fail there).
void requireKernelsDeclared(const std::string &File, const std::string &Source,
                            const std::vector<std::string> &Kernels);

/// A job on its own std::thread, Nice above the creating thread's nice value
/// (lowerThisThreadsPriority); OnDone, if any, runs on that thread once the result is ready.
/// The thread owns every OpenCL object it creates; only the programs cross over (kernels are
/// created from them on the main thread, so no cl_kernel is ever shared for clSetKernelArg).
class BackgroundBuild {
public:
  BackgroundBuild(std::function<TierBuildResult()> Job, size_t EventIndex,
                  int Nice = backgroundBuildNice(), std::function<void()> OnDone = nullptr);
  ~BackgroundBuild();
  BackgroundBuild(const BackgroundBuild &) = delete;
  BackgroundBuild &operator=(const BackgroundBuild &) = delete;

  bool ready() const;
  void wait() const { Result.wait(); }
  /// The result, after ready() or wait(): to look at, and a copy to keep.
  const TierBuildResult &result() const { return Result.get(); }
  TierBuildResult take() { return Result.get(); }
  size_t eventIndex() const { return EventIndex; }

private:
  std::shared_future<TierBuildResult> Result;
  std::thread Thread;
  size_t EventIndex;
};

/// Seconds on the steady clock (for build-event times).
double steadySeconds();

/// The text of a kernel source file; Error "PATH: cannot open kernel source".
std::string readKernelSource(const std::string &Path);

} // namespace texrender

#endif
