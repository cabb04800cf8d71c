// Ambient occlusion of a Renderer: by default every AO ray of every hit at once (the trace
// backend's aoOccluded: the OpenCL ao_trace launch of hits x aoSamples work-items, or one Embree
// stream of the rays ao_rays makes) and a reduction (ao_reduce), as the paper proposes;
// with RendererOptions::AoPerHitLoop the per-hit loop it argues against (ao_loop), which
// traces the same rays and gives the same AO, so that the two can be timed on one image.

#include "texrender/Renderer.h"

#include <algorithm>

namespace texrender {

void Renderer::runAo(const cl::Buffer &Active, int Count, FrameStats &Stats) {
  const cl_int Samples = Settings.AoSamples;
  if (Opts.AoPerHitLoop) {
    // The per-hit loop is an OpenCL kernel whatever the trace backend (it exists to be timed
    // against the parallel launch of the OpenCL traversal).
    cl::Kernel &AT = K["ao_loop"];
    AT.setArg(0, B["bvhNodes"]), AT.setArg(1, B["triangles"]);
    AT.setArg(2, B["triangleAttributes"]), AT.setArg(3, B["paths"]), AT.setArg(4, Active);
    AT.setArg(5, cl_int(Count)), AT.setArg(6, B["hits"]), AT.setArg(7, B["meshes"]);
    AT.setArg(8, B["materials"]), AT.setArg(9, Samples);
    AT.setArg(10, cl_float(Settings.AoDistance)), AT.setArg(11, cl_uint(Settings.Seed));
    AT.setArg(12, B["hitAttributes"]), AT.setArg(13, B["counters"]);
    Cl->launch(AT, size_t(Count), "ao_loop");
    Stats.AoWorkItemsPerLaunchMax = std::max<uint64_t>(Stats.AoWorkItemsPerLaunchMax, Count);
    return;
  }
  // Every AO ray of every hit at once: ao_trace (OpenCL) or one Embree stream (Trace.h).
  AoParams P;
  P.Samples = Samples, P.Distance = Settings.AoDistance;
  P.Seed = Settings.Seed;
  Tracer->aoOccluded(Active, Count, P);
  Stats.AoWorkItemsPerLaunchMax =
      std::max<uint64_t>(Stats.AoWorkItemsPerLaunchMax, uint64_t(Count) * Samples);
  cl::Kernel &AR = K["ao_reduce"];
  AR.setArg(0, B["aoOccluded"]), AR.setArg(1, B["hits"]), AR.setArg(2, B["triangleAttributes"]);
  AR.setArg(3, B["meshes"]), AR.setArg(4, B["materials"]), AR.setArg(5, cl_int(Count));
  AR.setArg(6, Samples), AR.setArg(7, B["hitAttributes"]);
  AR.setArg(8, B["counters"]);
  Cl->launch(AR, Count, "ao_reduce");
}

} // namespace texrender
