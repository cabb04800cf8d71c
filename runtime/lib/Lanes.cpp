#include "texrender/Lanes.h"
#include "texrender/Threads.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

namespace texrender {

namespace {

/// The rows a frame renders: the --region's, else the film's.
struct Rows {
  int X = 0, Y = 0, Width = 0, Height = 0;
};

Rows frameRows(const RenderSettings &G) {
  if (G.RegionWidth == 0)
    return {0, 0, G.Width, G.Height};
  return {G.RegionX, G.RegionY, G.RegionWidth, G.RegionHeight};
}

/// What one lane made.
struct LaneResult {
  std::vector<float> Image, Variance;
  FrameStats Stats;
  size_t MemoryBytes = 0;
  double ReadySeconds = 0, DoneSeconds = 0; // since the frame's start
  std::exception_ptr Failure;
};

void addStats(FrameStats &Sum, const FrameStats &L, bool First) {
  Sum.PrimaryRays += L.PrimaryRays;
  Sum.BounceRays += L.BounceRays;
  Sum.ShadowRays += L.ShadowRays;
  Sum.AoRays += L.AoRays;
  Sum.AoWorkItemsPerLaunchMax = std::max(Sum.AoWorkItemsPerLaunchMax, L.AoWorkItemsPerLaunchMax);
  Sum.NonFiniteSamples += L.NonFiniteSamples;
  Sum.SaturatedSamples += L.SaturatedSamples;
  Sum.Passes = std::max(Sum.Passes, L.Passes);
  Sum.SamplesDone = First ? L.SamplesDone : std::min(Sum.SamplesDone, L.SamplesDone);
  Sum.TimeLimited |= L.TimeLimited;
  Sum.Interrupted |= L.Interrupted;
  Sum.PassCut |= L.PassCut;
  Sum.Bounces = std::max(Sum.Bounces, L.Bounces);
  if (First)
    Sum.Tier = L.Tier;
  for (const auto &[Name, T] : L.Kernels) {
    KernelTiming &S = Sum.Kernels[Name];
    S.Launches += T.Launches, S.Seconds += T.Seconds, S.WorkItems += T.WorkItems;
  }
}

/// Copies lane I's rows (every Lanes-th row of the frame's, from row I) into Frame.
void scatterRows(const std::vector<float> &Lane, unsigned I, unsigned Lanes, int Width,
                 std::vector<float> &Frame) {
  const size_t Row = size_t(Width) * 3;
  for (size_t R = 0; R * Row < Lane.size(); ++R)
    std::copy_n(Lane.begin() + R * Row, Row, Frame.begin() + (I + R * Lanes) * Row);
}

} // namespace

std::string lanesUnavailable(Renderer &R, const RendererOptions &O, unsigned Lanes) {
  if (Lanes < 2)
    return "one render thread";
  if (std::string(R.tracer().name()) != "embree")
    return std::string("the trace backend is ") + R.tracer().name() + ", not embree";
  if (const unsigned Parts = R.cl().laneCapacity(); Parts < Lanes)
    return "the OpenCL device splits into " + std::to_string(Parts) + " one-unit parts, not " +
           std::to_string(Lanes);
  if (frameRows(R.settings()).Height < int(Lanes))
    return "fewer rows than lanes";
  if (O.CacheDir.empty())
    return "no program cache (each lane would build the kernels)";
  if (R.tiers().quickFirstBuildActive())
    return "the texture kernel is a quick first build (its optimised build would run per lane)";
  return "";
}

namespace {

/// The lanes' paths a pass together, in whole frames' (RendererOptions::MaxPathsPerPass):
/// half as many stages, each a host/worker handoff per lane, for twice the path buffers. At
/// 512x512, 16 spp on two cores, 8 passes of 2^18 paths a lane against 16 of 2^17: 1.8% faster
/// quiet, 2.2% beside a niced load (bench/threads.md).
constexpr size_t LanePathsFactor = 2;

/// The lanes' pass boundaries: progress told to O.AfterPass, and where each lane stops once
/// the frame stops (AfterPass returned false, or a lane failed).
class LaneStops {
public:
  LaneStops(unsigned Lanes, int Spp, int SppPerPass, const RendererOptions &O, double T0)
      : Done(Lanes, 0), Finished(Lanes, false), Spp(Spp), SppPerPass(SppPerPass), O(O), T0(T0) {}

  /// Lane I is at a pass boundary: whether it renders on.
  bool afterPass(unsigned I, const PassProgress &P) {
    std::lock_guard<std::mutex> Lock(M);
    Done[I] = P.SamplesDone;
    const int Fewest = *std::min_element(Done.begin(), Done.end());
    // O.AfterPass hears of progress once every lane has some.
    if (O.AfterPass && !Stop && Fewest > 0 &&
        !O.AfterPass(PassProgress{Fewest, P.Spp, steadySeconds() - T0, {}}))
      stop(I, P.SamplesDone, Spp);
    return !Stop || P.SamplesDone < Target;
  }
  /// Lane I's render has returned with Samples.
  void finished(unsigned I, int Samples) {
    std::lock_guard<std::mutex> Lock(M); // a stop from now on counts these samples
    Done[I] = Samples;
    Finished[I] = true;
  }
  /// Lane I (or, with I out of range, the frame) failed: every lane stops at its next boundary.
  void failed(unsigned I) {
    std::lock_guard<std::mutex> Lock(M);
    stop(I, 0, 0);
  }

private:
  /// Stops every lane at Target: the most samples a lane will have done at its next pass
  /// boundary (lane Caller is at one, with Samples; the others that run are in a pass), at most
  /// AtMost (0 after an error).
  void stop(unsigned Caller, int Samples, int AtMost) {
    int Most = Samples;
    for (unsigned J = 0; J < Done.size(); ++J)
      if (J != Caller)
        Most = std::max(Most, Finished[J] ? Done[J] : std::min(Spp, Done[J] + SppPerPass));
    Target = Stop ? std::min(Target, AtMost) : std::min(Most, AtMost);
    Stop = true;
  }

  std::mutex M;
  std::vector<int> Done;        // samples per lane at its last pass boundary
  std::vector<bool> Finished;   // its render has returned
  bool Stop = false;
  int Target = 0;               // once Stop: the samples every lane ends with
  const int Spp, SppPerPass;
  const RendererOptions &O;
  const double T0;
};

/// How many of F's rows lane I renders (rows I, I + Lanes, ...).
int laneRows(const Rows &F, unsigned I, unsigned Lanes) {
  return (F.Height - int(I) + int(Lanes) - 1) / int(Lanes);
}

/// Lane I's scene: S with G's settings, rendering rows I, I + Lanes, ... of F.
Scene laneScene(const Scene &S, const RenderSettings &G, const Rows &F, unsigned I, unsigned Lanes) {
  Scene LS = S;
  LS.Render = G;
  LS.Render.RegionX = F.X, LS.Render.RegionY = F.Y + int(I), LS.Render.RegionWidth = F.Width;
  LS.Render.RegionHeight = laneRows(F, I, Lanes);
  LS.Render.RegionRowStep = int(Lanes);
  return LS;
}

/// Runs Run(I) for I < Lanes, each on a thread of its own (LaneThread pins it; the caller stays
/// unpinned). Without a thread for a lane, the lanes started stop (Stops.failed) and the error
/// is thrown once they have.
template <typename F> void runLanes(unsigned Lanes, LaneStops &Stops, F &&Run) {
  std::vector<std::thread> Threads;
  try {
    for (unsigned I = 0; I < Lanes; ++I)
      Threads.emplace_back(Run, I);
  } catch (...) {
    Stops.failed(Lanes);
    for (std::thread &T : Threads)
      T.join();
    throw;
  }
  for (std::thread &T : Threads)
    T.join();
}

} // namespace

std::vector<float> renderInLanes(Renderer &R, const Scene &S, const Layout &L,
                                 const RendererOptions &O, unsigned Lanes, FrameStats &Stats,
                                 std::vector<float> *Variance, LaneReport *Report) {
  const double T0 = steadySeconds();
  const RenderSettings &G = R.settings();
  const Rows F = frameRows(G);
  // The lanes hold LanePathsFactor times the whole frame's paths a pass, shared evenly, and
  // every lane's passes are as many samples, so that stopped lanes end at the same sample
  // count (LaneStops). Lane 0 has the most rows.
  const size_t LanePaths = std::max<size_t>(1, LanePathsFactor * O.MaxPathsPerPass / Lanes);
  const size_t SppPerPass = std::clamp<size_t>(
      LanePaths / (size_t(F.Width) * size_t(laneRows(F, 0, Lanes))), 1,
      size_t(G.Spp));
  LaneStops Stops(Lanes, G.Spp, int(SppPerPass), O, T0);
  std::vector<LaneResult> Out(Lanes);
  runLanes(Lanes, Stops, [&](unsigned I) {
    try {
      LaneThread Here(I);
      const Scene LS = laneScene(S, G, F, I, Lanes);
      RendererOptions LO = O;
      LO.Lane = int(I);
      LO.Prebuilt = &R.sceneData();
      LO.PrebuiltTrace = &R.tracer();
      LO.MaxPathsPerPass = SppPerPass * size_t(F.Width) * size_t(LS.Render.RegionHeight);
      LO.AfterPass = [&Stops, I](const PassProgress &P) { return Stops.afterPass(I, P); };
      Renderer Lane(LS, L, LO);
      Out[I].ReadySeconds = steadySeconds() - T0;
      Out[I].Image = Lane.render(Out[I].Stats, Variance ? &Out[I].Variance : nullptr);
      Out[I].DoneSeconds = steadySeconds() - T0;
      Stops.finished(I, Out[I].Stats.SamplesDone);
      Out[I].MemoryBytes = Lane.cl().memoryTotal();
    } catch (...) {
      Out[I].Failure = std::current_exception();
      Stops.failed(I);
    }
  });
  for (const LaneResult &Res : Out)
    if (Res.Failure)
      std::rethrow_exception(Res.Failure);
  Stats = FrameStats();
  std::vector<float> Image(size_t(F.Width) * F.Height * 3);
  if (Variance)
    Variance->assign(Image.size(), 0.0f);
  LaneReport Lr{Lanes, 0, {}, {}};
  for (unsigned I = 0; I < Lanes; ++I) {
    addStats(Stats, Out[I].Stats, I == 0);
    scatterRows(Out[I].Image, I, Lanes, F.Width, Image);
    if (Variance)
      scatterRows(Out[I].Variance, I, Lanes, F.Width, *Variance);
    Lr.MemoryBytes += Out[I].MemoryBytes;
    Lr.ReadySeconds.push_back(Out[I].ReadySeconds);
    Lr.DoneSeconds.push_back(Out[I].DoneSeconds);
  }
  Stats.Seconds = steadySeconds() - T0;
  if (Report)
    *Report = std::move(Lr);
  return Image;
}

} // namespace texrender
