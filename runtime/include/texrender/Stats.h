#ifndef TEXRENDER_STATS_H
#define TEXRENDER_STATS_H

// stats.json (docs/runtime.md): per-kernel times from profiling events, rays per second by
// kind, kernel builds, attributes computed, memory, and one record per frame (edit mode).

#include "texrender/Renderer.h"

#include <nlohmann/json.hpp>

namespace texrender {

/// One rendered frame and the edit that preceded it.
struct FrameRecord {
  std::string EditText;        // "" for the first frame
  bool Rebuilt = false;
  bool BackgroundRebuild = false; // the edit regenerated the kernel on the background thread
  unsigned KernelBuilds = 0;   // builds this frame waited for (since the previous frame)
  unsigned BackgroundBuilds = 0; // builds the background thread finished since the previous frame
  double BuildWaitSeconds = 0; // wall seconds of the builds this frame waited for
  double EditSeconds = 0;      // applying the edit (re-encode + upload, or regenerate + build)
  double IdleSeconds = 0;      // a "wait" line: time waited for the background build
  FrameStats Frame;
};

/// The rays of a kind, the seconds of the kernel that traced them, and their rate.
nlohmann::json rayJson(uint64_t Count, double Seconds);

/// The whole stats.json. Frames: every frame rendered (the last one is the main result).
nlohmann::json statsJson(Renderer &R, const Layout &L, const std::vector<FrameRecord> &Frames,
                         double TotalSeconds);

} // namespace texrender

#endif
