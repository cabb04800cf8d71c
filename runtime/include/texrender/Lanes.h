#ifndef TEXRENDER_LANES_H
#define TEXRENDER_LANES_H

// A frame in lanes (docs/cli.md, "Lanes"): one lane per render thread, lane I on the device's
// compute unit I alone (an OpenCL sub-device; on PoCL's CPU device, its worker thread I) and a
// host thread of its own (its trace stages, pinned to CPU I with the pools), rendering the film
// rows I, I + N, I + 2N, ... of the frame with a Renderer of its own, which traces over the
// frame Renderer's Embree BVH (Trace::share: built once, on every thread). No lane waits at
// another's stage ends: a frame beside a competing load grows by the load's share of the
// cores, where the stages of one Renderer on every core wait, at each stage's end, for the
// core the load took last (bench/threads.md). Each row's pixels keep their film coordinates
// and random streams (raygen.cl), so the image is the whole frame's bit for bit.

#include "texrender/Renderer.h"

#include <string>
#include <vector>

namespace texrender {

/// Why R's next frame cannot render in Lanes lanes ("" when it can): one lane or none, a
/// device that does not split into as many one-unit parts, a trace backend other than Embree,
/// fewer film (or --region) rows than lanes, no program cache, or a texture kernel that is
/// a quick first build (its optimised build would run once per lane).
std::string lanesUnavailable(Renderer &R, const RendererOptions &O, unsigned Lanes);

/// What the lanes of a frame held, for stats.json.
struct LaneReport {
  unsigned Lanes = 0;
  size_t MemoryBytes = 0; // every lane's device memory, summed
  /// Per lane, seconds from the frame's start: until its Renderer was made (its scene upload
  /// and kernels loaded), and until its render returned.
  std::vector<double> ReadySeconds, DoneSeconds;
};

/// Renders the frame R would (R.settings(), with R's scene data; S and L as R was made from,
/// O its options) in Lanes lanes (lanesUnavailable(R, O, Lanes) must be ""), the lanes'
/// passes together twice O.MaxPathsPerPass paths, each lane's as many samples per pixel,
/// and returns the image as
/// R.render would (and the variance, if asked). Stats: the frame's wall clock; rays and kernel
/// timings summed over the lanes. O.AfterPass hears the fewest samples any lane has done,
/// once every lane has done a pass (PassProgress::Image is empty); once it returns false, each lane stops at the first pass
/// boundary where it has done as many samples as the lane furthest on had then, so that every
/// pixel averages the same samples. The first error of a lane is rethrown, after every lane
/// has stopped (at its next pass boundary).
std::vector<float> renderInLanes(Renderer &R, const Scene &S, const Layout &L,
                                 const RendererOptions &O, unsigned Lanes, FrameStats &Stats,
                                 std::vector<float> *Variance, LaneReport *Report = nullptr);

} // namespace texrender

#endif
