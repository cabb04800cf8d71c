#ifndef TEXRENDER_RENDERER_H
#define TEXRENDER_RENDERER_H

// The wavefront path tracer: separate kernels per stage (kernels/*.cl), launched per bounce
// over the compacted list of active paths:
//   raygen -> [closest_hit -> hit_attributes -> ao_trace/ao_reduce -> proctex -> shade ->
//   shadow -> compact]* -> accumulate
// hit_attributes, AO and the texture kernel run only when the layout needs them.

#include "texrender/ClContext.h"
#include "texrender/Layout.h"
#include "texrender/Scene.h"
#include "texrender/SceneData.h"
#include "texrender/TextureTiers.h"
#include "texrender/TierManager.h"
#include "texrender/Trace.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace texrender {

/// What render() has done so far, told to RendererOptions::AfterPass.
struct PassProgress {
  int SamplesDone = 0, Spp = 0;
  double Seconds = 0; // since render() began
  /// The image of the samples done (linear RGB, as render() returns): a read of the device.
  std::function<std::vector<float>()> Image;
};

/// $TEXRENDER_FIRST_BUILD: "optimised" turns the quick first build off; unset or "quick": on.
bool quickFirstBuildDefault();

struct RendererOptions {
  int Device = 0;
  std::string CacheDir = defaultCacheDir();
  std::string KernelDir;        // "" = kernelDirectory()
  bool CheckNan = false;        // --check-nan: stop at the first non-finite texture output
  size_t MaxPathsPerPass = 1u << 18;
  TierPolicy Tier = TierPolicy::Shape; // shape-mode layouts only (TextureTiers.h); texrender
                                       // picks auto for edit sessions
  /// interp-mode layouts: build the kernel with value-stack headroom (stackHeadroomOption, as
  /// shape mode's fallback has), so that a rewiring that needs a few more slots is an upload,
  /// not a build. texrender sets it for edit sessions.
  bool InterpStackHeadroom = false;
  /// TierManager::setQuickFirstBuild: a texture kernel not in the program cache renders first
  /// with a quick (uninlined) build while the optimised one builds behind it. On unless
  /// $TEXRENDER_FIRST_BUILD is "optimised".
  bool QuickFirstBuild = quickFirstBuildDefault();
  /// --ao-method=loop: one work-item per hit loops over its AO rays (ao_loop) instead of one
  /// work-item per AO ray (ao_trace + ao_reduce). Same rays, same image; kept to measure the
  /// paper's claim that the parallel launch is faster (bench/ao.py).
  bool AoPerHitLoop = false;
  /// --trace: the trace backend (Trace.h); Auto: Embree on CPU devices, OpenCL otherwise.
  TraceKind Trace = TraceKind::Auto;
  /// --time-limit: render() stops at the first pass boundary after this time (steadySeconds();
  /// 0: none) and averages the passes done (FrameStats::SamplesDone, TimeLimited).
  double Deadline = 0;
  /// Called with true before each pass of render() and with false once it is done (texrender's
  /// watchdog times single passes).
  std::function<void(bool InPass)> OnPass;
  /// Called after every pass of render() but the last (the device finished; texrender's
  /// progress bar, Ctrl-C and --watch's progressive image). Returning false stops the frame at
  /// this pass boundary: it averages the passes done (FrameStats::Interrupted).
  std::function<bool(const PassProgress &)> AfterPass;
  /// Called between the stages of a pass's bounces (the device idle). Returning true
  /// abandons the pass in flight: its samples are never accumulated, and render() returns the
  /// passes done before it (FrameStats::Interrupted, PassCut). texrender --watch cuts a pass
  /// when an edit comes, whose accumulation restarts anyway.
  std::function<bool()> CutPass;
  /// A lane of a frame (Lanes.h): renders on the device's compute unit Lane alone (ClContext).
  /// -1: the whole device.
  int Lane = -1;
  /// The scene's host data already built (a lane's: the frame's Renderer has it), copied
  /// instead of built again; null: built from the scene.
  const SceneData *Prebuilt = nullptr;
  /// The trace backend of the frame's Renderer (a lane's), whose acceleration structure this
  /// renderer's backend shares (Trace::share); null: built for this renderer.
  const texrender::Trace *PrebuiltTrace = nullptr; // qualified: the field Trace names the kind
};


/// Counts of one frame.
struct FrameStats {
  double Seconds = 0;           // wall clock of render()
  uint64_t PrimaryRays = 0;
  uint64_t BounceRays = 0;      // closest-hit rays after the first segment
  uint64_t ShadowRays = 0;
  uint64_t AoRays = 0;
  uint64_t AoWorkItemsPerLaunchMax = 0;
  uint64_t NonFiniteSamples = 0; // NaN or infinite path samples, dropped from the image
  uint64_t SaturatedSamples = 0; // finite samples that made a pixel sum saturate at FLT_MAX
  unsigned Passes = 0;
  int SamplesDone = 0;          // samples per pixel rendered (fewer than asked when TimeLimited)
  bool TimeLimited = false;     // RendererOptions::Deadline stopped the frame early
  bool Interrupted = false;     // RendererOptions::AfterPass or CutPass stopped the frame early
  bool PassCut = false;         // RendererOptions::CutPass abandoned a pass in flight
  unsigned Bounces = 0;         // bounce iterations summed over passes
  std::string Tier;             // the texture kernel that ran: interp, shape, inline, wavefront
  std::map<std::string, KernelTiming> Kernels;
};

/// Where the fixed kernels are: $TEXRENDER_KERNELS, else <executable>/../kernels, else
/// <executable>/kernels.
std::string kernelDirectory();

/// The hit-attributes mask (bit 1 << TEXCC_ATTR_*) of layout.json "attributes".
uint32_t attributeMaskOf(const Layout &L);

class Renderer {
public:
  Renderer(const Scene &S, const Layout &L, const RendererOptions &Opts);
  /// Waits for background builds (their results are dropped).
  ~Renderer();
  Renderer(const Renderer &) = delete;
  Renderer &operator=(const Renderer &) = delete;

  /// Renders S.Render (size, spp, depth) and returns linear RGB (3 floats per pixel, row 0
  /// at the top), averaged over the samples. Variance (optional): the estimated variance of
  /// each pixel's value, per channel.
  std::vector<float> render(FrameStats &Stats, std::vector<float> *Variance = nullptr);

  /// Replaces the fake stack and the attributes the textures read (a live edit in
  /// interp/wavefront/shape mode): an upload, no build.
  void applyArguments(const std::vector<uint8_t> &ArgsBin, const std::vector<std::string> &Attributes);
  /// Replaces the texture kernel and its layout (a regenerated proctex.cl): a build unless the
  /// program cache has it. Shape mode, tier auto: the interp fallback is built now and an
  /// uncached shape kernel on the background thread.
  void setLayout(const Layout &L);

  /// Shape mode, tier auto: the graph's shapes changed but the interp fallback kernel can run
  /// the re-encoded ArgsBin. Frames render with it at once; MakeLayout (on the background
  /// thread: texcc regenerating the graph) gives the new layout, whose shape and interp
  /// kernels are built there too. At the first frame after they are ready, Reencode (on the
  /// caller's thread; it must stay valid until then) fills the new layout's args.bin and
  /// attributes with the edits made since, and the renderer switches to it.
  void switchShapes(const std::vector<uint8_t> &ArgsBin, const std::vector<std::string> &Attributes,
                    std::function<Layout()> MakeLayout, std::function<void(Layout &)> Reencode);
  /// The texture kernels, their tiers and builds (TierManager.h): the session's one way to
  /// them (TierManager::subscribe for its events, collect at its idle boundaries, the watch
  /// session's switches setDeferFallbackBuilds and setQuickTier).
  TierManager &tiers() { return *Tiers; }
  const TierManager &tiers() const { return *Tiers; }
  TierPolicy tierPolicy() const { return Opts.Tier; }

  /// For tests: one jittered camera ray per pixel, the hit attributes of the first hits
  /// (Mask: bits 1 << TEXCC_ATTR_*), with AO computed when the mask has the AO bit.
  std::vector<TexccHitAttrs> primaryHitAttributes(uint32_t Mask, FrameStats &Stats);

  ClContext &cl() { return *Cl; }
  const SceneData &sceneData() const { return Data; }
  /// The trace backend in use (closest hit, shadow and AO rays).
  const Trace &tracer() const { return *Tracer; }
  RenderSettings &settings() { return Settings; }
  uint32_t attributeMask() const { return AttrMask; }
  bool runsAo() const { return (AttrMask >> TEXCC_ATTR_AO) & 1u; }
  bool runsTextures() const { return HasTextureWork; }

private:
  void buildFixedKernels();
  void uploadScene();
  void allocateWorkBuffers(size_t MaxPaths);
  void uploadLayoutData();
  /// The image of the first NumPixels sums over Done samples (linear RGB).
  std::vector<float> averageSums(size_t NumPixels, int Done);
  /// Points each mesh at its material's index in Lay, by the material's name in scene.json:
  /// a regenerated layout may number the materials differently. A name Lay lacks is an error.
  void mapMeshMaterials();
  /// Stops early (Stats.PassCut) when Opts.CutPass asks to, after a bounce.
  int traceBounces(int NumPaths, FrameStats &Stats, bool StopAfterAttributes);
  /// AO of the Count hits of the active list: ao_trace + ao_reduce, or ao_loop.
  void runAo(const cl::Buffer &Active, int Count, FrameStats &Stats);
  void runTextures(int NumActive);
  /// --check-nan: throws, naming the material, the node and the pixel, if a texture output
  /// of the NumActive hits in Active is NaN or infinite.
  void checkTextureOutputs(const cl::Buffer &Active, int NumActive);
  /// Throws, naming node, line and pixel, if a safety check of user code tripped in this
  /// bounce's texture kernels (the fault record; Faults.cpp).
  void checkTextureFaults(const cl::Buffer &Active);
  void setSceneArgs();
  std::string programOptions() const;

  std::unique_ptr<ClContext> Cl;
  Scene SceneDesc;
  Layout Lay;
  RendererOptions Opts;
  RenderSettings Settings;
  SceneData Data;
  std::string KernelDir;
  uint32_t AttrMask = 0;
  bool HasTextureWork = false;

  std::map<std::string, cl::Kernel> K;      // fixed kernels by name

  double Epoch = 0;                         // steadySeconds() at construction
  /// The texture kernels: tiers, builds, adoption (after Cl: it uses it, and is destroyed
  /// first, waiting for its background builds).
  std::unique_ptr<TierManager> Tiers;

  std::map<std::string, cl::Buffer> B;      // device buffers by name
  std::unique_ptr<Trace> Tracer;            // the trace stages (after B: it refers to it)
  size_t Capacity = 0;                      // paths the work buffers hold
  int CapacityAo = 0;
};

} // namespace texrender

#endif
