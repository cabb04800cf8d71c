#ifndef TEXRENDER_TOOL_OPTIONS_H
#define TEXRENDER_TOOL_OPTIONS_H

// texrender's command line (docs/runtime.md): the options, their parsing and checks, and the
// usage text. texrender.cpp runs what they ask for.

#include "texrender/ClContext.h"
#include "texrender/TextureTiers.h"
#include "texrender/Trace.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace texrender {

struct Options {
  std::string Scene, Textures, Output, Stats, Variance, EditScript, KernelDir, CacheDir = defaultCacheDir();
  std::optional<int> Spp, Width, Height, MaxDepth, AoSamples, Seed;
  std::optional<float> AoDistance;
  std::optional<std::array<int, 4>> Region; // --region X,Y,W,H
  int Frame = 0;
  float Fps = 24;
  double TimeLimit = 0; // --time-limit seconds; 0: none
  std::vector<std::string> Sets;
  int Device = 0;
  std::optional<int> Threads; // --threads N (1..MaxThreads); default: every core (Threads.h)
  bool Lanes = true;          // --lanes on|off (Lanes.h)
  TraceKind Trace = TraceKind::Auto; // --trace
  std::optional<TierPolicy> Tier; // default: auto in an edit session, else shape
  bool Watch = false, Control = false, ReducedFirstPass = true;
  double FirstPassBudgetMs = 60; // --first-pass-budget
  // --serve[=PORT] / --listen ADDR: Serve is set; Forward: every other argument, as given.
  bool Serve = false;
  int ServePort = 8642;
  std::string Listen = "127.0.0.1";
  bool ListenGiven = false;
  std::vector<std::string> Forward;
  // --view-transform, --look, --exposure, --gamma (a .png's Color Management; default: the
  // scene's film.view) and --ocio-config (default: $OCIO).
  std::optional<std::string> ViewTransform, Look;
  std::optional<float> Exposure, Gamma;
  std::string OcioConfig;
  std::string FromExr; // --from-exr FILE: no render; FILE's pixels become -o's PNG
  bool Quiet = false, ForceProgress = false, ListDevices = false, CheckNan = false, AoLoop = false, Interactive = false;
};

/// --threads' upper bound.
constexpr int MaxThreads = 1024;

/// The options of texrender's command line, checked against each other and each output's
/// folder checked; -h/--help and --version print and exit 0, any error throws Error.
Options parseArgs(int Argc, char **Argv);

} // namespace texrender

#endif
