// The OpenCL trace backend: the kernels closest_hit, shadow and ao_trace traverse the wide BVH
// (4 children a node, built by Embree's BVH builder: Bvh.cpp; traversal: rt_bvh.h). The
// default on non-CPU devices.

#include "texrender/Trace.h"
#include "texrender/Error.h"

namespace texrender {

TraceKind parseTraceKind(const std::string &Name) {
  if (Name == "auto")
    return TraceKind::Auto;
  if (Name == "opencl")
    return TraceKind::OpenCl;
  if (Name == "embree")
    return TraceKind::Embree;
  throw Error("--trace: expected opencl, embree or auto, got '" + Name + "'");
}

const char *traceKindName(TraceKind K) {
  switch (K) {
  case TraceKind::Auto:
    return "auto";
  case TraceKind::OpenCl:
    return "opencl";
  case TraceKind::Embree:
    return "embree";
  }
  return "?";
}

TraceKind resolveTraceKind(TraceKind Asked, ClContext &Cl) {
  if (Asked != TraceKind::Auto)
    return Asked;
  return (Cl.device().getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) ? TraceKind::Embree
                                                                      : TraceKind::OpenCl;
}

std::unique_ptr<Trace> makeTrace(TraceKind Asked, const TraceContext &C) {
  return resolveTraceKind(Asked, C.Cl) == TraceKind::Embree ? makeEmbreeTrace(C)
                                                            : makeOpenClTrace(C);
}

namespace {

class OpenClTrace final : public Trace {
public:
  explicit OpenClTrace(const TraceContext &C) : C(C) {}
  const char *name() const override { return "opencl"; }
  double buildSeconds() const override { return 0.0; }
  std::unique_ptr<Trace> share(const TraceContext &To) const override {
    return std::make_unique<OpenClTrace>(To); // the SAH BVH is in To's buffers
  }

  void closestHit(const cl::Buffer &Active, int Count, const std::string &Stage) override {
    cl::Kernel &CH = C.K.at("closest_hit");
    CH.setArg(0, C.B.at("bvhNodes")), CH.setArg(1, C.B.at("triangles"));
    CH.setArg(2, C.B.at("paths")), CH.setArg(3, Active), CH.setArg(4, cl_int(Count));
    CH.setArg(5, C.B.at("hits"));
    C.Cl.launch(CH, size_t(Count), Stage);
  }

  void shadow(const cl::Buffer &Active, int Count) override {
    cl::Kernel &SD = C.K.at("shadow");
    SD.setArg(0, C.B.at("bvhNodes")), SD.setArg(1, C.B.at("triangles"));
    SD.setArg(2, C.B.at("shadowRays")), SD.setArg(3, C.B.at("paths"));
    SD.setArg(4, Active), SD.setArg(5, cl_int(Count));
    C.Cl.launch(SD, size_t(Count), "shadow");
  }

  void aoOccluded(const cl::Buffer &Active, int Count, const AoParams &P) override {
    cl::Kernel &AT = C.K.at("ao_trace");
    AT.setArg(0, C.B.at("bvhNodes")), AT.setArg(1, C.B.at("triangles"));
    AT.setArg(2, C.B.at("triangleAttributes")), AT.setArg(3, C.B.at("paths"));
    AT.setArg(4, Active), AT.setArg(5, cl_int(Count)), AT.setArg(6, C.B.at("hits"));
    AT.setArg(7, C.B.at("meshes")), AT.setArg(8, C.B.at("materials"));
    AT.setArg(9, cl_int(P.Samples)), AT.setArg(10, cl_float(P.Distance));
    AT.setArg(11, cl_uint(P.Seed)), AT.setArg(12, C.B.at("aoOccluded"));
    C.Cl.launch(AT, size_t(Count) * size_t(P.Samples), "ao_trace");
  }

private:
  TraceContext C;
};

} // namespace

std::unique_ptr<Trace> makeOpenClTrace(const TraceContext &C) {
  return std::make_unique<OpenClTrace>(C);
}

} // namespace texrender
