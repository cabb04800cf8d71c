// The Embree trace backend (the default on CPU devices): Embree 3 builds the BVH over the
// scene's triangles (in SceneData's order, so that Embree's primID is the triangle id the other
// stages use) and answers closest_hit and shadow with ray streams (rtcIntersect1M,
// rtcOccluded1M) and ao_trace with ray packets (rtcOccluded8), on renderThreads() threads
// (texrender --threads, Threads.h). It reads and writes the very buffers the OpenCL stages use,
// mapped in place (on a CPU device the map is the buffer's memory: no copy per bounce). The AO
// rays are made by the OpenCL kernel ao_rays (the same rays ao_trace traces); Embree traces
// each hit's rays as one 8-wide packet (rtcOccluded8): they share an origin, so the packet
// walks the BVH's nodes near it once for all of them (bench/cycles.md, 2026-12-04: faster
// than 64-ray streams of the same rays).
// Each stage's time (map, trace, unmap) is recorded as that stage's kernel time in stats.json.

#include "texrender/Trace.h"
#include "texrender/Error.h"
#include "texrender/Threads.h"
#include "texcc/OutOfMemory.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace texrender {

namespace {

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Runs Fn(Begin, End) over [0, N) in chunks of Chunk, on renderThreads() threads (the calling
/// one among them; Threads.h): the OpenCL stages have finished, so PoCL's pool of as many
/// threads is idle meanwhile. Thread T runs on CPU T when the pools are pinned, as PoCL's
/// worker T does (pinRenderThread): woken for the next stage, each finds its own core.
template <typename F> void parallelChunks(size_t N, size_t Chunk, F &&Fn) {
  const size_t Chunks = (N + Chunk - 1) / Chunk;
  const size_t Threads = std::min<size_t>(renderThreads(), Chunks);
  std::atomic<size_t> Next{0};
  auto Work = [&] {
    for (size_t C; (C = Next++) < Chunks;)
      Fn(C * Chunk, std::min(N, (C + 1) * Chunk));
  };
  std::vector<std::thread> Pool;
  for (size_t T = 1; T < Threads; ++T) {
    try {
      Pool.emplace_back([&Work, T] {
        pinRenderThread(unsigned(T));
        Work();
      });
    } catch (const std::system_error &) {
      break; // no room for another thread (its stack): the threads started do all the chunks
    }
  }
  Work();
  for (std::thread &T : Pool)
    T.join();
}

/// A buffer mapped for the host for the lifetime of the object (unmapped by the destructor).
class Mapped {
public:
  Mapped(ClContext &Cl, const cl::Buffer &B, size_t Bytes, cl_map_flags Flags)
      : Cl(Cl), Buf(B) {
    Ptr = Cl.queue().enqueueMapBuffer(Buf, CL_TRUE, Flags, 0, std::max<size_t>(Bytes, 1));
  }
  ~Mapped() {
    try {
      Cl.queue().enqueueUnmapMemObject(Buf, Ptr);
    } catch (const cl::Error &) {
      // Unwinding from an error already: the queue is failing, nothing more to do.
    }
  }
  template <typename T> T *as() const { return static_cast<T *>(Ptr); }

private:
  ClContext &Cl;
  cl::Buffer Buf;
  void *Ptr = nullptr;
};

constexpr size_t Stream = 64;    // rays per rtcIntersect1M / rtcOccluded1M call
constexpr size_t Chunk = 2048;   // rays per work unit of a thread

/// The context filter of the AO rays: a ray never hits the triangle it starts on (its ray id;
/// ao_rays passes it in origin.w), as Cycles' AO rays skip their own primitive (ao.cl's
/// ao_origin: they start on the hit point).
void skipOwnTriangle(const RTCFilterFunctionNArguments *A) {
  for (unsigned I = 0; I < A->N; ++I)
    if (A->valid[I] && RTCHitN_primID(A->hit, A->N, I) == RTCRayN_id(A->ray, A->N, I))
      A->valid[I] = 0;
}

/// Where an Embree device's errors go: the first message, kept for check(). Shared by the
/// backends tracing over that device's scene (Trace::share), and locked: they trace on
/// different threads.
struct ErrorSink {
  std::mutex Lock;
  std::string Last;
};

void embreeError(void *User, RTCError Code, const char *Message) {
  auto *Sink = static_cast<ErrorSink *>(User);
  try {
    std::lock_guard<std::mutex> Hold(Sink->Lock);
    if (Sink->Last.empty())
      Sink->Last = std::string(Message ? Message : "") + " (Embree error " +
                   std::to_string(int(Code)) + ")";
  } catch (const std::bad_alloc &) {
    // Out of memory: check() reads the code from rtcGetDeviceError; nothing may unwind into Embree.
  }
}

class EmbreeTrace final : public Trace {
public:
  explicit EmbreeTrace(const TraceContext &C) : C(C) {
    double T0 = seconds();
    Device = rtcNewDevice(embreeDeviceConfig().c_str()); // its pool builds the BVH
    if (!Device && rtcGetDeviceError(nullptr) == RTC_ERROR_OUT_OF_MEMORY)
      throw std::bad_alloc(); // named by makeEmbreeTrace's step (Embree's threads did not start)
    if (!Device)
      throw Error("cannot start Embree: " + std::to_string(int(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(Device, embreeError, Errors.get());
    if (!rtcGetDeviceProperty(Device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
      throw Error("this Embree has no filter functions (AO rays skip their own triangle)");
    Scene = rtcNewScene(Device);
    // The AO rays' filter (skipOwnTriangle). Not robust: ao.cl's AO rays start a little behind
    // the hit point, so the fast test finds a face through it as Cycles' robust one does.
    rtcSetSceneFlags(Scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    // Medium (binned SAH), as Cycles builds its Embree BVH by default: high (spatial splits)
    // cost a third of texrender's start-up for no measured frame-time gain (bench/startup.md).
    rtcSetSceneBuildQuality(Scene, RTC_BUILD_QUALITY_MEDIUM);
    const size_t NT = C.Data.Tris.size();
    if (NT > 0) {
      RTCGeometry G = rtcNewGeometry(Device, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto *V = static_cast<float *>(rtcSetNewGeometryBuffer(
          G, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * NT));
      auto *I = static_cast<unsigned *>(rtcSetNewGeometryBuffer(
          G, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), NT));
      check("cannot allocate Embree's vertex buffer");
      for (size_t K = 0; K < 3 * NT; ++K) {
        const Vec3 &P = C.Data.Positions[K];
        V[3 * K] = P[0], V[3 * K + 1] = P[1], V[3 * K + 2] = P[2];
        I[K] = unsigned(K);
      }
      rtcCommitGeometry(G);
      rtcAttachGeometry(Scene, G);
      rtcReleaseGeometry(G);
    }
    rtcCommitScene(Scene);
    check("cannot build Embree's BVH");
    BuildSeconds = seconds() - T0;
  }

  /// Traces over From's scene (retained: it lives as long as either backend).
  EmbreeTrace(const TraceContext &C, const EmbreeTrace &From)
      : C(C), Device(From.Device), Scene(From.Scene), Errors(From.Errors) {
    rtcRetainDevice(Device);
    rtcRetainScene(Scene);
  }

  ~EmbreeTrace() override {
    if (Scene)
      rtcReleaseScene(Scene);
    if (Device)
      rtcReleaseDevice(Device);
  }

  const char *name() const override { return "embree"; }
  double buildSeconds() const override { return BuildSeconds; }
  std::unique_ptr<Trace> share(const TraceContext &To) const override {
    return std::make_unique<EmbreeTrace>(To, *this);
  }

  void closestHit(const cl::Buffer &Active, int Count, const std::string &Stage) override {
    if (Count <= 0)
      return;
    C.Cl.finish(); // the stages before have written the rays
    double T0 = seconds();
    {
      const size_t N = size_t(Count);
      Mapped Paths(C.Cl, C.B.at("paths"), C.Cl.memory().at("paths"), CL_MAP_READ);
      Mapped Act(C.Cl, Active, N * sizeof(cl_int), CL_MAP_READ);
      Mapped Hits(C.Cl, C.B.at("hits"), N * sizeof(RtHit), CL_MAP_WRITE_INVALIDATE_REGION);
      const RtPath *P = Paths.as<RtPath>();
      const cl_int *A = Act.as<cl_int>();
      RtHit *H = Hits.as<RtHit>();
      const bool Coherent = Stage == "closest_hit_primary";
      parallelChunks(N, Chunk, [&](size_t Begin, size_t End) {
        RTCIntersectContext Ctx;
        rtcInitIntersectContext(&Ctx);
        Ctx.flags = Coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                             : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
        RTCRayHit R[Stream];
        for (size_t S = Begin; S < End; S += Stream) {
          const size_t M = std::min(Stream, End - S);
          for (size_t J = 0; J < M; ++J) {
            const RtPath &Pa = P[A[S + J]];
            RTCRayHit &X = R[J];
            X.ray.org_x = Pa.origin.s[0], X.ray.org_y = Pa.origin.s[1], X.ray.org_z = Pa.origin.s[2];
            X.ray.dir_x = Pa.dir.s[0], X.ray.dir_y = Pa.dir.s[1], X.ray.dir_z = Pa.dir.s[2];
            X.ray.tnear = 0.0f, X.ray.tfar = INFINITY, X.ray.time = 0.0f;
            X.ray.mask = ~0u, X.ray.id = unsigned(J), X.ray.flags = 0;
            X.hit.geomID = RTC_INVALID_GEOMETRY_ID, X.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
          }
          rtcIntersect1M(Scene, &Ctx, R, unsigned(M), sizeof(RTCRayHit));
          // Same conventions as closest_hit.cl: t, the triangle (BVH order), the barycentrics
          // of v1 and v2; a miss is tri -1, t = tmax, u = v = 0.
          for (size_t J = 0; J < M; ++J) {
            const RTCRayHit &X = R[J];
            RtHit &Out = H[S + J];
            if (X.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
              Out.t = INFINITY, Out.tri = -1, Out.u = 0.0f, Out.v = 0.0f;
            } else {
              Out.t = X.ray.tfar, Out.tri = int(X.hit.primID), Out.u = X.hit.u, Out.v = X.hit.v;
            }
          }
        }
      });
    }
    C.Cl.finish(); // the unmaps
    C.Cl.addHostTiming(Stage, seconds() - T0, uint64_t(Count));
  }

  void shadow(const cl::Buffer &Active, int Count) override {
    if (Count <= 0)
      return;
    C.Cl.finish();
    double T0 = seconds();
    {
      const size_t N = size_t(Count);
      Mapped Rays(C.Cl, C.B.at("shadowRays"), N * sizeof(RtShadowRay), CL_MAP_READ);
      Mapped Act(C.Cl, Active, N * sizeof(cl_int), CL_MAP_READ);
      Mapped Paths(C.Cl, C.B.at("paths"), C.Cl.memory().at("paths"), CL_MAP_READ | CL_MAP_WRITE);
      const RtShadowRay *SR = Rays.as<RtShadowRay>();
      const cl_int *A = Act.as<cl_int>();
      RtPath *P = Paths.as<RtPath>();
      parallelChunks(N, Chunk, [&](size_t Begin, size_t End) {
        occludedStream(SR, Begin, End, [&](size_t I, bool Blocked) {
          if (!Blocked) {
            RtPath &Pa = P[A[I]];
            for (int K = 0; K < 3; ++K)
              Pa.radiance.s[K] += SR[I].contrib.s[K];
          }
        });
      });
    }
    C.Cl.finish();
    C.Cl.addHostTiming("shadow", seconds() - T0, uint64_t(Count));
  }

  void aoOccluded(const cl::Buffer &Active, int Count, const AoParams &Prm) override {
    const size_t N = size_t(Count) * size_t(Prm.Samples);
    if (N == 0)
      return;
    const size_t Bytes = N * sizeof(RtShadowRay);
    if (!C.B.count("aoRays") || C.Cl.memory().at("aoRays") < Bytes)
      C.B["aoRays"] = C.Cl.allocate("aoRays", Bytes, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR);
    cl::Kernel &AR = C.K.at("ao_rays");
    AR.setArg(0, C.B.at("triangles")), AR.setArg(1, C.B.at("triangleAttributes"));
    AR.setArg(2, C.B.at("paths")), AR.setArg(3, Active), AR.setArg(4, cl_int(Count));
    AR.setArg(5, C.B.at("hits")), AR.setArg(6, C.B.at("meshes"));
    AR.setArg(7, C.B.at("materials")), AR.setArg(8, cl_int(Prm.Samples));
    AR.setArg(9, cl_float(Prm.Distance)), AR.setArg(10, cl_uint(Prm.Seed));
    AR.setArg(11, C.B.at("aoRays"));
    C.Cl.launch(AR, size_t(Count), "ao_rays"); // one work-item per hit, Samples rays each
    C.Cl.finish();
    double T0 = seconds();
    {
      Mapped Rays(C.Cl, C.B.at("aoRays"), Bytes, CL_MAP_READ);
      Mapped Occ(C.Cl, C.B.at("aoOccluded"), N, CL_MAP_WRITE_INVALIDATE_REGION);
      const RtShadowRay *R = Rays.as<RtShadowRay>();
      cl_uchar *O = Occ.as<cl_uchar>();
      // All AO rays of all hits, in chunks of whole hits; each hit's rays as 8-wide packets
      // (one for aoSamples <= 8). A hit without AO is one marked ray (contrib.w < 0), skipped
      // with its run: its aoOccluded slots stay as they are, ao_reduce reads only the slots
      // of hits with AO.
      const size_t Run = size_t(Prm.Samples);
      parallelChunks(N, std::max<size_t>(1, Chunk / Run) * Run, [&](size_t Begin, size_t End) {
        RTCIntersectContext Ctx;
        rtcInitIntersectContext(&Ctx);
        Ctx.filter = skipOwnTriangle;
        RTCRay8 X;
        alignas(32) int Valid[8];
        for (size_t H = Begin; H < End; H += Run) {
          if (R[H].contrib.s[3] < 0.0f)
            continue;
          for (size_t S = H; S < H + Run; S += 8) {
            const size_t M = std::min<size_t>(8, H + Run - S);
            for (size_t J = 0; J < 8; ++J) {
              const RtShadowRay &Y = R[S + std::min(J, M - 1)]; // lanes past M: off, valid data
              Valid[J] = J < M ? -1 : 0;
              X.org_x[J] = Y.origin.s[0], X.org_y[J] = Y.origin.s[1], X.org_z[J] = Y.origin.s[2];
              X.dir_x[J] = Y.dir.s[0], X.dir_y[J] = Y.dir.s[1], X.dir_z[J] = Y.dir.s[2];
              X.tnear[J] = 0.0f, X.tfar[J] = Y.dir.s[3], X.time[J] = 0.0f;
              X.mask[J] = ~0u, X.flags[J] = 0;
              std::memcpy(&X.id[J], &Y.origin.s[3], sizeof(unsigned)); // the ray's own triangle
            }
            rtcOccluded8(Valid, Scene, &Ctx, &X);
            for (size_t J = 0; J < M; ++J)
              O[S + J] = X.tfar[J] == -INFINITY ? 1 : 0; // Embree's mark of an occluded ray
          }
        }
      });
    }
    C.Cl.finish();
    C.Cl.addHostTiming("ao_trace", seconds() - T0, uint64_t(N));
  }

private:
  /// Any-hit queries of the rays R[Begin, End) (RtShadowRay: dir.w = tmax; contrib.w <= 0:
  /// not traced, reported as blocked); calls Done(I, Blocked) for each.
  template <typename F>
  void occludedStream(const RtShadowRay *R, size_t Begin, size_t End, F &&Done) const {
    RTCIntersectContext Ctx;
    rtcInitIntersectContext(&Ctx);
    RTCRay X[Stream];
    size_t Index[Stream];
    for (size_t S = Begin; S < End;) {
      size_t M = 0;
      for (; S < End && M < Stream; ++S) {
        const RtShadowRay &Y = R[S];
        if (Y.contrib.s[3] <= 0.0f) {
          Done(S, true);
          continue;
        }
        RTCRay &Ray = X[M];
        Ray.org_x = Y.origin.s[0], Ray.org_y = Y.origin.s[1], Ray.org_z = Y.origin.s[2];
        Ray.dir_x = Y.dir.s[0], Ray.dir_y = Y.dir.s[1], Ray.dir_z = Y.dir.s[2];
        Ray.tnear = 0.0f, Ray.tfar = Y.dir.s[3], Ray.time = 0.0f;
        Ray.mask = ~0u, Ray.id = unsigned(M), Ray.flags = 0;
        Index[M++] = S;
      }
      if (M == 0)
        continue;
      rtcOccluded1M(Scene, &Ctx, X, unsigned(M), sizeof(RTCRay));
      for (size_t J = 0; J < M; ++J)
        Done(Index[J], X[J].tfar == -INFINITY); // Embree sets tfar to -inf when occluded
    }
  }

  void check(const char *What) {
    if (rtcGetDeviceError(Device) == RTC_ERROR_OUT_OF_MEMORY)
      throw std::bad_alloc(); // named by makeEmbreeTrace's step
    std::lock_guard<std::mutex> Hold(Errors->Lock);
    if (!Errors->Last.empty())
      throw Error(std::string(What) + ": " + Errors->Last);
  }

  TraceContext C;
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  std::shared_ptr<ErrorSink> Errors = std::make_shared<ErrorSink>();
  double BuildSeconds = 0; // 0: shared
};

} // namespace

std::unique_ptr<Trace> makeEmbreeTrace(const TraceContext &C) {
  return texcc::whileAllocating("building the BVH (Embree)",
                                [&] { return std::make_unique<EmbreeTrace>(C); });
}

} // namespace texrender
