#include "texrender/Stats.h"
#include "texcc/Kernel/Attributes.h"

namespace texrender {

using nlohmann::json;

json rayJson(uint64_t Count, double Seconds) {
  return {{"count", Count},
          {"seconds", Seconds},
          {"perSecond", Seconds > 0 ? double(Count) / Seconds : 0.0}};
}

namespace {

double kernelSeconds(const FrameStats &F, const std::string &Name) {
  auto It = F.Kernels.find(Name);
  return It == F.Kernels.end() ? 0.0 : It->second.Seconds;
}

json frameJson(const FrameStats &F) {
  json Kernels = json::object();
  double Sum = 0;
  for (auto &[Name, T] : F.Kernels) {
    Kernels[Name] = {{"launches", T.Launches}, {"seconds", T.Seconds}, {"workItems", T.WorkItems}};
    Sum += T.Seconds;
  }
  json J;
  J["renderSeconds"] = F.Seconds;
  J["kernelSeconds"] = Sum;
  J["passes"] = F.Passes;
  J["nonFiniteSamples"] = F.NonFiniteSamples;
  J["saturatedSamples"] = F.SaturatedSamples;
  J["bounces"] = F.Bounces;
  J["kernels"] = Kernels;
  J["rays"] = {
      {"primary", rayJson(F.PrimaryRays, kernelSeconds(F, "closest_hit_primary"))},
      {"bounce", rayJson(F.BounceRays, kernelSeconds(F, "closest_hit_bounce"))},
      {"shadow", rayJson(F.ShadowRays, kernelSeconds(F, "shadow"))},
      {"ao", rayJson(F.AoRays, kernelSeconds(F, "ao_trace") + kernelSeconds(F, "ao_loop"))}};
  // The AO rays are traced by ao_trace, or by ao_loop with --ao-method=loop.
  auto AO = F.Kernels.find("ao_trace");
  if (AO == F.Kernels.end())
    AO = F.Kernels.find("ao_loop");
  J["ao"] = {{"launches", AO == F.Kernels.end() ? 0u : AO->second.Launches},
             {"workItems", AO == F.Kernels.end() ? 0ull : (unsigned long long)AO->second.WorkItems},
             {"maxWorkItemsPerLaunch", F.AoWorkItemsPerLaunchMax}};
  return J;
}

json buildEventsJson(const std::vector<BuildEvent> &Events) {
  json A = json::array();
  for (const BuildEvent &E : Events)
    A.push_back({{"kernel", E.Kernel},
                 {"reason", E.Reason},
                 {"background", E.Background},
                 {"startSeconds", E.StartSeconds},
                 {"readySeconds", E.ReadySeconds < 0 ? json(nullptr) : json(E.ReadySeconds)},
                 {"seconds", E.ReadySeconds < 0 ? json(nullptr) : json(E.ReadySeconds - E.StartSeconds)},
                 {"firstFrame", E.FirstFrame < 0 ? json(nullptr) : json(E.FirstFrame)},
                 {"superseded", E.Superseded},
                 {"error", E.Error.empty() ? json(nullptr) : json(E.Error)}});
  return A;
}

} // namespace

json statsJson(Renderer &R, const Layout &L, const std::vector<FrameRecord> &Frames,
               double TotalSeconds) {
  json J;
  J["texrender"] = 1;
  J["device"] = R.cl().deviceName();
  J["mode"] = L.Mode;
  const RenderSettings &S = R.settings();
  J["image"] = {{"width", S.Width}, {"height", S.Height}, {"spp", S.Spp}, {"maxDepth", S.MaxDepth}};
  J["triangles"] = R.sceneData().Tris.size();
  J["bvhNodes"] = R.sceneData().Tree.Nodes.size();
  // The trace backend (Trace.h) and the build time of each acceleration structure made: the
  // wide BVH (always; the OpenCL traversal and the host tests use it) and Embree's scene BVH
  // (embree only).
  J["trace"] = R.tracer().name();
  J["bvhBuildSeconds"] = {{"wide", R.sceneData().Tree.BuildSeconds},
                          {"embree", std::string(R.tracer().name()) == "embree"
                                         ? json(R.tracer().buildSeconds()) : json(nullptr)}};
  J["lights"] = R.sceneData().Lights.size();
  std::vector<std::string> Attrs;
  for (unsigned I = 0; I < texcc::kernel::NumAttributes; ++I)
    if (R.attributeMask() & (1u << I))
      Attrs.push_back(texcc::kernel::attributeName(I));
  J["attributesComputed"] = Attrs;
  J["aoEnabled"] = R.runsAo();
  J["aoSamples"] = S.AoSamples;
  J["textureKernel"] = R.runsTextures();
  J["kernelBuilds"] = R.cl().kernelBuilds();
  J["backgroundKernelBuilds"] = R.cl().backgroundBuilds();
  J["tierPolicy"] = L.Caps.InterpFallback ? json(tierPolicyName(R.tierPolicy())) : json(nullptr);
  J["textureBuilds"] = buildEventsJson(R.tiers().buildEvents());
  J["programCacheHits"] = R.cl().cacheHits();
  J["memoryBytes"] = R.cl().memoryTotal();
  J["memory"] = R.cl().memory();
  J["totalSeconds"] = TotalSeconds;
  if (!Frames.empty()) {
    json Last = frameJson(Frames.back().Frame);
    for (auto &[K, V] : Last.items())
      J[K] = V;
  }
  json Fs = json::array();
  for (size_t I = 0; I < Frames.size(); ++I) {
    const FrameRecord &F = Frames[I];
    json Fj = {{"index", I},
               {"edit", F.EditText.empty() ? json(nullptr) : json(F.EditText)},
               {"kernelBuilds", F.KernelBuilds},
               {"backgroundBuilds", F.BackgroundBuilds},
               {"buildWaitSeconds", F.BuildWaitSeconds},
               {"tier", F.Frame.Tier.empty() ? json(nullptr) : json(F.Frame.Tier)},
               {"rebuilt", F.Rebuilt},
               {"backgroundRebuild", F.BackgroundRebuild},
               {"idleSeconds", F.IdleSeconds},
               {"editSeconds", F.EditSeconds},
               {"renderSeconds", F.Frame.Seconds},
               {"editToFrameSeconds", F.EditText.empty() ? json(nullptr)
                                                         : json(F.EditSeconds + F.Frame.Seconds)},
               {"rays", frameJson(F.Frame)["rays"]}};
    Fs.push_back(Fj);
  }
  J["frames"] = Fs;
  return J;
}

} // namespace texrender
