#ifndef TEXRENDER_CLCONTEXT_H
#define TEXRENDER_CLCONTEXT_H

// The OpenCL host layer: device selection, an in-order profiling queue, a program cache keyed
// by source hash + build options + device (program binaries on disk), checked launches whose
// profiling events are summed per kernel name, and a tally of the memory allocated.

#ifndef CL_HPP_TARGET_OPENCL_VERSION
#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#endif
#ifndef CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_ENABLE_EXCEPTIONS
#endif
#include <CL/opencl.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace texrender {

/// Time and count of one kernel's launches (from CL_PROFILING_COMMAND_START/END).
struct KernelTiming {
  unsigned Launches = 0;
  double Seconds = 0.0;
  uint64_t WorkItems = 0;
};

/// Every OpenCL device of every platform, in discovery order ("N: name (platform)").
std::vector<std::string> listDevices();

class ClContext {
public:
  /// Opens device DeviceIndex (the order of listDevices()). CacheDir: where program binaries
  /// are kept ("" = no disk cache). Lane >= 0: only the device's compute unit Lane (a
  /// sub-device of one unit; on PoCL's CPU device, its worker thread Lane), for a lane of a
  /// frame (Lanes.h); the programs and their cache are the whole device's.
  ClContext(int DeviceIndex, std::string CacheDir, int Lane = -1);

  /// Builds (or loads from the cache) a program. Name is used in messages (the file);
  /// KeyExtra joins the cache key (e.g. the text of the headers the source includes). Throws
  /// Error with the device, the options and the build log on failure. Safe to call from a
  /// background thread (OpenCL 1.2 builds are thread-safe); Background says who called, for
  /// the counts: a foreground build is one a frame waits for. WarmUp (if any) runs on the
  /// program, built or loaded, before its binary is stored: PoCL compiles a work-group function
  /// per local size and grid class at a kernel's first launch, and a binary taken after those
  /// launches carries them (bench/coldstart.md), so a program loaded from the cache compiles
  /// nothing at any image size or spp.
  cl::Program buildProgram(const std::string &Name, const std::string &Source,
                           const std::string &Options, const std::string &KeyExtra = "",
                           bool Background = false,
                           const std::function<void(const cl::Program &)> &WarmUp = nullptr);
  /// Whether buildProgram would find the program in the disk cache (no build from source).
  bool isCached(const std::string &Source, const std::string &Options,
                const std::string &KeyExtra = "") const;
  /// A read-only folder of prebuilt program binaries (scripts/build.sh fills build/programs
  /// with the fixed kernels), looked up after the cache folder; "" = none.
  void setPrebuiltDir(std::string Dir) { PrebuiltDir = std::move(Dir); }

  /// Creates a buffer of Bytes (at least 1) and counts it under Label in the memory tally.
  cl::Buffer allocate(const std::string &Label, size_t Bytes, cl_mem_flags Flags);
  /// Same, with initial contents copied from Data.
  cl::Buffer allocateWith(const std::string &Label, const void *Data, size_t Bytes,
                          cl_mem_flags Flags);
  void write(const cl::Buffer &B, const void *Data, size_t Bytes, size_t Offset = 0);
  void read(const cl::Buffer &B, void *Data, size_t Bytes, size_t Offset = 0);

  /// Enqueues K over GlobalSize work-items (rounded up to the work-group multiple) and records
  /// its profiling event under TimingName. A zero size enqueues nothing.
  void launch(cl::Kernel &K, size_t GlobalSize, const std::string &TimingName);
  /// Waits for the queue and adds the profiling times of the pending launches.
  void finish();

  const std::string &deviceName() const { return DeviceName; }
  /// How many one-unit lanes the device splits into (CL_DEVICE_PARTITION_EQUALLY; 0: none).
  unsigned laneCapacity();
  cl::Context &context() { return Ctx; }
  cl::CommandQueue &queue() { return Queue; }

  /// Programs built from source, in all (foreground + background) and per caller.
  unsigned kernelBuilds() const { return Builds + BackgroundBuilds; }
  unsigned foregroundBuilds() const { return Builds; }
  unsigned backgroundBuilds() const { return BackgroundBuilds; }
  unsigned cacheHits() const { return CacheHits; }
  cl::Device &device() { return Device; }
  const std::map<std::string, KernelTiming> &timings() const { return Timings; }
  void resetTimings() { Timings.clear(); }
  /// Adds a stage that ran on the host (a host trace backend, Trace.h) to the timings.
  void addHostTiming(const std::string &Name, double Seconds, uint64_t WorkItems) {
    KernelTiming &T = Timings[Name];
    ++T.Launches, T.Seconds += Seconds, T.WorkItems += WorkItems;
  }
  const std::map<std::string, size_t> &memory() const { return Memory; }
  size_t memoryTotal() const;

private:
  struct Pending {
    cl::Event Ev;
    std::string Name;
    size_t WorkItems;
  };
  std::string cachePath(const std::string &Key) const;
  /// The cached binary of Key: the cache folder's, else the prebuilt folder's; "" if neither.
  std::string cachedBinary(const std::string &Key) const;
  std::string cacheKey(const std::string &Source, const std::string &Options,
                       const std::string &KeyExtra) const;
  cl::Program buildFromSource(const std::string &Name, const std::string &Source,
                              const std::string &Options, bool Background);
  void storeBinary(cl::Program &P, const std::string &Path);

  cl::Device Device;
  cl::Context Ctx;
  cl::CommandQueue Queue;
  std::string DeviceName;
  std::string DeviceKey;
  std::string CacheDir;
  std::string PrebuiltDir;
  std::atomic<unsigned> Builds{0}, BackgroundBuilds{0}, CacheHits{0};
  std::vector<Pending> PendingEvents;
  std::map<std::string, KernelTiming> Timings;
  std::map<std::string, size_t> Memory;
};

/// The default program-cache folder: $TEXRENDER_CACHE_DIR, else $XDG_CACHE_HOME/texcc, else
/// $HOME/.cache/texcc, else "" (no disk cache).
std::string defaultCacheDir();

/// PoCL compiles a second work-group function for launches of this many work-items or more.
constexpr size_t LargeGridItems = 65536;

/// Launches every kernel of P once over one work-group of 64 items and once over
/// LargeGridItems, with every buffer argument a small dummy buffer and every scalar argument 0:
/// texrender's kernels all return at once when their count is 0. PoCL compiles its work-group
/// functions (one for small grids, one for grids of 65536 items or more) here rather than at
/// a frame's first launch. A kernel whose argument kinds cannot be queried is skipped.
void warmUpAllKernels(ClContext &Cl, const cl::Program &P);

/// 64-bit FNV-1a, as 16 hex digits.
std::string hashHex(const std::string &Data);

/// Runs F and turns a cl::Error into texrender::Error naming the call and the error code.
std::string clErrorName(cl_int Code);

} // namespace texrender

#endif
