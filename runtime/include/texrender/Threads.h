#ifndef TEXRENDER_THREADS_H
#define TEXRENDER_THREADS_H

// How many threads render a frame (texrender --threads, docs/cli.md). A frame's stages take
// turns: an OpenCL stage runs on the CPU device's pool (PoCL's pthread device), then a trace
// stage on the trace backend's threads (TraceEmbree.cpp's ray chunks; Embree's own pool builds
// its BVHs). Each pool gets the same count, and only one of them works at a time. Implemented
// in ClContext.cpp, which owns the first OpenCL call.

#include <string>

namespace texrender {

/// Sets the thread count of every pool: N, or with N = 0 every core (the default). PoCL reads
/// its pool size from the environment (set here) when the OpenCL platform is first queried, so
/// this must come once, before the first OpenCL call of the process and before threads that
/// read the environment start: afterwards it throws Error. The first device discovery applies
/// the default when nothing called it. The count is fixed per process.
void setRenderThreads(unsigned N);

/// The thread count of every pool: setRenderThreads's N, else the cores this process may run on
/// (its CPU affinity mask; at least 1). On a lane's thread (LaneThread): 1.
unsigned renderThreads();

/// Makes the calling thread lane I of a frame (Lanes.h) for the object's lifetime: its trace
/// stages run on it alone (renderThreads() is 1 there), and it runs on CPU I when the pools
/// are pinned, as the OpenCL sub-device of lane I does (PoCL's worker I).
class LaneThread {
public:
  explicit LaneThread(unsigned I);
  ~LaneThread();
  LaneThread(const LaneThread &) = delete;
  LaneThread &operator=(const LaneThread &) = delete;
};

/// Whether a count was given (setRenderThreads with N >= 1: texrender --threads).
bool renderThreadsGiven();

/// Whether each pool's thread I runs on CPU I: the pools have N >= 2 threads and the process
/// may run on CPUs 0..N-1 and no other (decided with the pool's size; PoCL's POCL_AFFINITY
/// pins its worker I to CPU I by number, so no other mask can be pinned). A thread woken for
/// the next stage then has its own core instead of queueing behind another process's thread
/// on a core a sibling already took (docs/cli.md, bench/threads.md).
bool renderThreadsPinned();

/// Pins the calling thread, the pool's thread I, to CPU I when the pools are pinned.
void pinRenderThread(unsigned I);

/// The configuration string of rtcNewDevice: "threads=N" with N = renderThreads() (on a lane's
/// thread: 1).
std::string embreeDeviceConfig();

} // namespace texrender

#endif
