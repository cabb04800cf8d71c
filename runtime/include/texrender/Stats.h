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
  unsigned KernelBuilds = 0;   // builds performed between the previous frame and this one
  double EditSeconds = 0;      // applying the edit (re-encode + upload, or regenerate + build)
  FrameStats Frame;
};

/// The rays of a kind, the seconds of the kernel that traced them, and their rate.
nlohmann::json rayJson(uint64_t Count, double Seconds);

/// The whole stats.json. Frames: every frame rendered (the last one is the main result).
nlohmann::json statsJson(Renderer &R, const Layout &L, const std::vector<FrameRecord> &Frames,
                         double TotalSeconds);

} // namespace texrender

#endif
