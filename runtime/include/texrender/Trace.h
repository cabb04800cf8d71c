#ifndef TEXRENDER_TRACE_H
#define TEXRENDER_TRACE_H

// The trace stages of the renderer (closest hit, shadow rays, AO rays) behind one interface,
// with two backends:
//   - OpenClTrace (TraceOpenCl.cpp): the OpenCL kernels closest_hit, shadow and ao_trace over
//     the host-built SAH BVH (kernels/common/rt_bvh.h);
//   - EmbreeTrace (TraceEmbree.cpp): Embree 3 on the host, answering the same stages over the
//     same buffers (paths, active, hits, shadowRays, aoOccluded: kernels/common/rt_types.h),
//     mapped in place (zero-copy on a CPU device), on every core.
// Every other stage stays OpenCL. A backend reads its inputs and writes its outputs through the
// Renderer's buffer table, so that switching backends changes nothing else.

#include "texrender/ClContext.h"
#include "texrender/SceneData.h"

#include <map>
#include <memory>
#include <string>

namespace texrender {

enum class TraceKind { Auto, OpenCl, Embree };

/// "auto", "opencl" or "embree" (throws Error otherwise).
TraceKind parseTraceKind(const std::string &Name);
const char *traceKindName(TraceKind K);

/// What a backend works on: the Renderer's context, fixed kernels and buffers (by name:
/// bvhNodes, triangles, triangleAttributes, meshes, materials, paths, hits, shadowRays,
/// aoOccluded) and the scene's triangles (BVH order: triangle ids are the same in both).
struct TraceContext {
  ClContext &Cl;
  std::map<std::string, cl::Kernel> &K;
  std::map<std::string, cl::Buffer> &B;
  const SceneData &Data;
};

/// The parameters of one AO stage.
struct AoParams {
  int Samples = 0;
  float Distance = 0;
  unsigned Seed = 0;
};

class Trace {
public:
  virtual ~Trace() = default;
  /// "opencl" or "embree".
  virtual const char *name() const = 0;
  /// Seconds this backend spent building its acceleration structure (0 when it uses the
  /// SAH BVH that SceneData built).
  virtual double buildSeconds() const = 0;
  /// hits[i] = the closest hit of the ray of paths[active[i]], i < Count. Stage: the timing
  /// name (closest_hit_primary or closest_hit_bounce).
  virtual void closestHit(const cl::Buffer &Active, int Count, const std::string &Stage) = 0;
  /// Shadow ray i (shadowRays[i], valid when contrib.w > 0) adds contrib to
  /// paths[active[i]].radiance when nothing lies within its tmax (dir.w).
  virtual void shadow(const cl::Buffer &Active, int Count) = 0;
  /// aoOccluded[i * Samples + j] = 1 when AO ray j of hit i is blocked within Distance, for
  /// the hits whose material reads AO (the slots of the other hits are 0 with OpenCL and left
  /// as they were with Embree: ao_reduce reads only the former); ao_reduce averages them.
  virtual void aoOccluded(const cl::Buffer &Active, int Count, const AoParams &P) = 0;
  /// The same backend over the same scene on another renderer's context and buffers (a
  /// lane's, Lanes.h), sharing this one's acceleration structure instead of building its
  /// own. Both may trace at once, from different threads.
  virtual std::unique_ptr<Trace> share(const TraceContext &C) const = 0;
};

/// Auto: Embree on a CPU device, OpenCL otherwise.
TraceKind resolveTraceKind(TraceKind Asked, ClContext &Cl);
std::unique_ptr<Trace> makeOpenClTrace(const TraceContext &C);
std::unique_ptr<Trace> makeEmbreeTrace(const TraceContext &C);
std::unique_ptr<Trace> makeTrace(TraceKind Asked, const TraceContext &C);

} // namespace texrender

#endif
