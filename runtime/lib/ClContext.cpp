#include "texrender/ClContext.h"
#include "texrender/Error.h"
#include "texrender/Threads.h"
#include "texcc/Support/AtomicWrite.h"
#include "texcc/Support/File.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sched.h>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texrender {

std::string clErrorName(cl_int Code) {
  switch (Code) {
  case CL_DEVICE_NOT_FOUND: return "CL_DEVICE_NOT_FOUND";
  case CL_OUT_OF_RESOURCES: return "CL_OUT_OF_RESOURCES";
  case CL_OUT_OF_HOST_MEMORY: return "CL_OUT_OF_HOST_MEMORY";
  case CL_MEM_OBJECT_ALLOCATION_FAILURE: return "CL_MEM_OBJECT_ALLOCATION_FAILURE";
  case CL_BUILD_PROGRAM_FAILURE: return "CL_BUILD_PROGRAM_FAILURE";
  case CL_INVALID_VALUE: return "CL_INVALID_VALUE";
  case CL_INVALID_BINARY: return "CL_INVALID_BINARY";
  case CL_INVALID_BUILD_OPTIONS: return "CL_INVALID_BUILD_OPTIONS";
  case CL_INVALID_KERNEL_NAME: return "CL_INVALID_KERNEL_NAME";
  case CL_INVALID_ARG_INDEX: return "CL_INVALID_ARG_INDEX";
  case CL_INVALID_ARG_VALUE: return "CL_INVALID_ARG_VALUE";
  case CL_INVALID_ARG_SIZE: return "CL_INVALID_ARG_SIZE";
  case CL_INVALID_KERNEL_ARGS: return "CL_INVALID_KERNEL_ARGS";
  case CL_INVALID_WORK_GROUP_SIZE: return "CL_INVALID_WORK_GROUP_SIZE";
  case CL_INVALID_BUFFER_SIZE: return "CL_INVALID_BUFFER_SIZE";
  case CL_INVALID_MEM_OBJECT: return "CL_INVALID_MEM_OBJECT";
  case CL_PLATFORM_NOT_FOUND_KHR: return "CL_PLATFORM_NOT_FOUND_KHR";
  default: return "OpenCL error " + std::to_string(Code);
  }
}

std::string hashHex(const std::string &Data) {
  uint64_t H = 1469598103934665603ull;
  for (unsigned char C : Data) {
    H ^= C;
    H *= 1099511628211ull;
  }
  char Buf[17];
  std::snprintf(Buf, sizeof Buf, "%016llx", static_cast<unsigned long long>(H));
  return Buf;
}

std::string defaultCacheDir() {
  if (const char *D = std::getenv("TEXRENDER_CACHE_DIR"))
    return D;
  if (const char *X = std::getenv("XDG_CACHE_HOME"); X && *X)
    return std::string(X) + "/texcc";
  if (const char *H = std::getenv("HOME"); H && *H)
    return std::string(H) + "/.cache/texcc";
  return "";
}

namespace {
unsigned ThreadsGiven = 0; // setRenderThreads's N; 0: every core
bool PoolSized = false;    // sizePoclPool ran: the count is fixed for the process
bool Pinned = false;       // each pool's thread I runs on CPU I (sizePoclPool)
std::mutex PoolMutex;
thread_local bool OnLane = false; // the calling thread is a lane's (LaneThread)
} // namespace

static unsigned coresAvailable() {
  cpu_set_t Set;
  CPU_ZERO(&Set);
  if (sched_getaffinity(0, sizeof Set, &Set) == 0 && CPU_COUNT(&Set) > 0)
    return unsigned(CPU_COUNT(&Set));
  return std::max(1u, std::thread::hardware_concurrency());
}

unsigned renderThreads() {
  if (OnLane)
    return 1;
  return ThreadsGiven ? ThreadsGiven : coresAvailable();
}

LaneThread::LaneThread(unsigned I) {
  OnLane = true;
  pinRenderThread(I);
}

LaneThread::~LaneThread() { OnLane = false; }

bool renderThreadsGiven() { return ThreadsGiven != 0; }

std::string embreeDeviceConfig() { return "threads=" + std::to_string(renderThreads()); }

bool renderThreadsPinned() { return Pinned; }

void pinRenderThread(unsigned I) {
  if (!Pinned)
    return;
  cpu_set_t Set;
  CPU_ZERO(&Set);
  CPU_SET(I, &Set);
  pthread_setaffinity_np(pthread_self(), sizeof Set, &Set); // best effort: unpinned on failure
}

/// Whether the pools are pinned: N threads, the process may run on exactly CPUs 0..N-1, and
/// N > 1. PoCL's POCL_AFFINITY pins its worker I to CPU I (by index, whatever the mask), so
/// only then is its pinning right.
static bool pinnable(unsigned N) {
  cpu_set_t Set;
  CPU_ZERO(&Set);
  if (N < 2 || sched_getaffinity(0, sizeof Set, &Set) != 0 || unsigned(CPU_COUNT(&Set)) != N)
    return false;
  for (unsigned I = 0; I < N; ++I)
    if (!CPU_ISSET(I, &Set))
      return false;
  return true;
}

/// PoCL's pthread device starts one worker per compute unit, and takes the count from
/// POCL_MAX_PTHREAD_COUNT (PoCL 3; later versions also read POCL_CPU_MAX_CU_COUNT when it is
/// unset) when the platform is first queried, raised to POCL_PTHREAD_MIN_THREADS /
/// POCL_CPU_MIN_CU_COUNT. --threads sets them; without it, a POCL_MAX_PTHREAD_COUNT already in
/// the environment is kept (bench/per_hit.py runs PoCL on one thread that way), else it is set
/// to the cores this process may run on (PoCL itself counts every core of the machine, also
/// those outside the affinity mask). POCL_AFFINITY is set when the pools are pinned
/// (renderThreadsPinned), else cleared. Runs once: by setRenderThreads, or by the first device
/// discovery. The environment is changed here only, before PoCL or texrender start threads
/// that could read it (texrender calls setRenderThreads right after parsing its options).
static void sizePoclPool(unsigned N) {
  std::lock_guard<std::mutex> Lock(PoolMutex);
  if (PoolSized)
    return;
  PoolSized = true;
  ThreadsGiven = N;
  if (!N && std::getenv("POCL_MAX_PTHREAD_COUNT"))
    return;
  const unsigned Pool = ThreadsGiven ? ThreadsGiven : coresAvailable();
  const std::string Count = std::to_string(Pool);
  Pinned = pinnable(Pool);
  if (Pinned)
    setenv("POCL_AFFINITY", "1", 1);
  else
    unsetenv("POCL_AFFINITY"); // PoCL would pin worker I to CPU I whatever the mask
  setenv("POCL_MAX_PTHREAD_COUNT", Count.c_str(), 1);
  setenv("POCL_CPU_MAX_CU_COUNT", Count.c_str(), 1);
  unsetenv("POCL_PTHREAD_MIN_THREADS");
  unsetenv("POCL_CPU_MIN_CU_COUNT");
}

void setRenderThreads(unsigned N) {
  {
    std::lock_guard<std::mutex> Lock(PoolMutex);
    if (PoolSized)
      throw Error("the thread count is set once, before the first OpenCL call (PoCL sizes its "
                  "pool then)");
  }
  sizePoclPool(N);
}

/// The first call of device discovery that failed, and how.
struct DiscoveryFailure {
  std::string Call;
  cl_int Code = CL_SUCCESS;
};

static std::vector<std::pair<cl::Device, std::string>>
allDevices(DiscoveryFailure *Failure = nullptr) {
  std::vector<std::pair<cl::Device, std::string>> Out;
  std::vector<cl::Platform> Platforms;
  auto failed = [&](const char *Call, const cl::Error &E) {
    if (Failure && Failure->Code == CL_SUCCESS)
      *Failure = {Call, E.err()};
  };
  sizePoclPool(0); // the default, unless setRenderThreads came first
  try {
    cl::Platform::get(&Platforms);
  } catch (const cl::Error &E) {
    failed("clGetPlatformIDs", E);
    return Out;
  }
  for (auto &P : Platforms) {
    std::vector<cl::Device> Devs;
    try {
      P.getDevices(CL_DEVICE_TYPE_ALL, &Devs);
    } catch (const cl::Error &E) {
      if (E.err() != CL_DEVICE_NOT_FOUND)
        failed("clGetDeviceIDs", E);
      continue;
    }
    for (auto &D : Devs)
      Out.push_back({D, D.getInfo<CL_DEVICE_NAME>() + " (" + P.getInfo<CL_PLATFORM_NAME>() + ")"});
  }
  return Out;
}

/// Whether an OpenCL ICD is installed for the ICD loader to load (a vendors file, or the
/// loader's environment variables naming one).
static bool icdInstalled() {
  if (std::getenv("OCL_ICD_VENDORS") || std::getenv("OCL_ICD_FILENAMES"))
    return true;
  std::error_code Ec;
  for (const auto &E : fs::directory_iterator("/etc/OpenCL/vendors", Ec))
    if (E.path().extension() == ".icd")
      return true;
  return false;
}

/// Why no device was found. Under a memory limit the platform itself cannot start: the ICD
/// loader fails to load PoCL (no platform, though one is installed) or PoCL's device discovery
/// runs out of host memory; that says so, rather than suggest installing an ICD.
static std::string noDeviceMessage(const DiscoveryFailure &F) {
  const bool OutOfMemory = F.Code == CL_OUT_OF_HOST_MEMORY || F.Code == CL_OUT_OF_RESOURCES;
  if (OutOfMemory || (F.Code == CL_PLATFORM_NOT_FOUND_KHR && icdInstalled()))
    return "no OpenCL device found: the OpenCL platform could not be initialised (" + F.Call +
           ": " + clErrorName(F.Code) +
           (OutOfMemory ? "" : ", though an ICD is installed") +
           "); memory may be the cause (a `ulimit -v` or a container's limit)";
  return "no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)";
}

std::vector<std::string> listDevices() {
  std::vector<std::string> Names;
  for (auto &D : allDevices())
    Names.push_back(std::to_string(Names.size()) + ": " + D.second);
  return Names;
}

ClContext::ClContext(int DeviceIndex, std::string CacheDirIn, int Lane)
    : CacheDir(std::move(CacheDirIn)) {
  DiscoveryFailure Failure;
  auto Devs = allDevices(&Failure);
  if (Devs.empty())
    throw Error(noDeviceMessage(Failure));
  if (DeviceIndex < 0 || DeviceIndex >= static_cast<int>(Devs.size()))
    throw Error("--device " + std::to_string(DeviceIndex) + ": no such OpenCL device (" +
                std::to_string(Devs.size()) + " found; use 0.." +
                std::to_string(Devs.size() - 1) + ")");
  Device = Devs[DeviceIndex].first;
  DeviceName = Devs[DeviceIndex].second;
  try {
    // The program cache's key stays the whole device's: a sub-device runs the same binaries.
    DeviceKey = DeviceName + "|" + Device.getInfo<CL_DRIVER_VERSION>() + "|" +
                Device.getInfo<CL_DEVICE_VERSION>();
    if (Lane >= 0) {
      if (unsigned(Lane) >= laneCapacity())
        throw Error("OpenCL device '" + DeviceName + "' has no lane " + std::to_string(Lane) +
                    " (it splits into " + std::to_string(laneCapacity()) + " one-unit parts)");
      const cl_device_partition_property Equally[] = {CL_DEVICE_PARTITION_EQUALLY, 1, 0};
      std::vector<cl::Device> Parts;
      Device.createSubDevices(Equally, &Parts);
      Device = Parts.at(size_t(Lane));
    }
    Ctx = cl::Context(Device);
    Queue = cl::CommandQueue(Ctx, Device, CL_QUEUE_PROFILING_ENABLE);
  } catch (const cl::Error &E) {
    throw Error(std::string("cannot open OpenCL device '") + DeviceName + "': " + E.what() +
                " failed with " + clErrorName(E.err()));
  }
}

unsigned ClContext::laneCapacity() {
  try {
    for (cl_device_partition_property P : Device.getInfo<CL_DEVICE_PARTITION_PROPERTIES>())
      if (P == CL_DEVICE_PARTITION_EQUALLY)
        return Device.getInfo<CL_DEVICE_PARTITION_MAX_SUB_DEVICES>();
  } catch (const cl::Error &) {
    // A device that cannot say: no lanes.
  }
  return 0;
}

std::string ClContext::cachePath(const std::string &Key) const {
  if (CacheDir.empty())
    return "";
  return CacheDir + "/programs/" + Key + ".bin";
}

static std::string buildLog(const cl::Program &P, const cl::Device &D) {
  try {
    return P.getBuildInfo<CL_PROGRAM_BUILD_LOG>(D);
  } catch (const cl::Error &) {
    return "(no build log)";
  }
}

std::string ClContext::cacheKey(const std::string &Source, const std::string &Options,
                                const std::string &KeyExtra) const {
  return hashHex(Source + '\0' + Options + '\0' + DeviceKey + '\0' + KeyExtra);
}

std::string ClContext::cachedBinary(const std::string &Key) const {
  std::error_code Ec;
  std::string Path = cachePath(Key);
  if (!Path.empty() && fs::exists(Path, Ec))
    return Path;
  if (PrebuiltDir.empty())
    return "";
  Path = PrebuiltDir + "/" + Key + ".bin";
  return fs::exists(Path, Ec) ? Path : "";
}

bool ClContext::isCached(const std::string &Source, const std::string &Options,
                         const std::string &KeyExtra) const {
  return !cachedBinary(cacheKey(Source, Options, KeyExtra)).empty();
}

cl::Program ClContext::buildProgram(const std::string &Name, const std::string &Source,
                                    const std::string &Options, const std::string &KeyExtra,
                                    bool Background,
                                    const std::function<void(const cl::Program &)> &WarmUp) {
  const std::string Key = cacheKey(Source, Options, KeyExtra);
  if (std::string Cached = cachedBinary(Key); !Cached.empty()) {
    std::string Text, Why;
    texcc::readRegularFile(Cached, Text, Why); // unreadable: empty, built from source below
    std::vector<unsigned char> Bin(Text.begin(), Text.end());
    cl::Program P;
    try {
      cl::Program::Binaries Bins{Bin};
      P = cl::Program(Ctx, {Device}, Bins);
      P.build({Device}, Options.c_str());
      ++CacheHits;
    } catch (const cl::Error &) {
      P = cl::Program(); // a stale or foreign binary: built from source below
    }
    if (P()) {
      if (WarmUp)
        WarmUp(P); // nothing to compile when the binary carries its work-group functions
      return P;
    }
  }
  cl::Program P = buildFromSource(Name, Source, Options, Background);
  if (WarmUp)
    WarmUp(P);
  if (std::string Path = cachePath(Key); !Path.empty())
    storeBinary(P, Path); // after the warm-up: the binary carries the compiled launches
  return P;
}

cl::Program ClContext::buildFromSource(const std::string &Name, const std::string &Source,
                                       const std::string &Options, bool Background) {
  cl::Program P;
  try {
    P = cl::Program(Ctx, Source);
    ++(Background ? BackgroundBuilds : Builds);
    P.build({Device}, Options.c_str());
  } catch (const cl::Error &E) {
    std::string Log = buildLog(P, Device);
    throw Error("kernel build failed: " + Name + " on '" + DeviceName + "' with options '" +
                Options + "' (" + clErrorName(E.err()) + ")\n" + Log);
  }
  return P;
}

void ClContext::storeBinary(cl::Program &P, const std::string &Path) {
  try {
    auto Bins = P.getInfo<CL_PROGRAM_BINARIES>();
    if (Bins.empty() || Bins[0].empty())
      return;
    std::error_code EC;
    fs::create_directories(fs::path(Path).parent_path(), EC);
    // A temporary per write: a background build may store while the main thread does.
    std::string Ignored;
    texcc::writeFileAtomically(
        Path, std::string(reinterpret_cast<const char *>(Bins[0].data()), Bins[0].size()),
        Ignored);
  } catch (const cl::Error &) {
    // The cache is an optimisation: a device without binaries still renders.
  }
}

void warmUpAllKernels(ClContext &Cl, const cl::Program &P) {
  std::vector<cl::Kernel> Kernels;
  try {
    cl::Program(P).createKernels(&Kernels);
  } catch (const cl::Error &) {
    return;
  }
  cl::Buffer Dummy(Cl.context(), CL_MEM_READ_WRITE, 4096);
  cl::CommandQueue Queue(Cl.context(), Cl.device());
  for (cl::Kernel &K : Kernels) {
    try {
      const cl_uint Args = K.getInfo<CL_KERNEL_NUM_ARGS>();
      for (cl_uint A = 0; A < Args; ++A) {
        if (K.getArgInfo<CL_KERNEL_ARG_ADDRESS_QUALIFIER>(A) == CL_KERNEL_ARG_ADDRESS_PRIVATE) {
          const cl_uint Zero = 0; // texrender's scalar kernel arguments are 4-byte int/uint/float
          K.setArg(A, sizeof Zero, &Zero);
        } else {
          K.setArg(A, Dummy);
        }
      }
      Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
      Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(LargeGridItems), cl::NDRange(64));
    } catch (const cl::Error &) {
      // No argument information (or an unusual argument): its first frame compiles it.
    }
  }
  Queue.finish();
}

cl::Buffer ClContext::allocate(const std::string &Label, size_t Bytes, cl_mem_flags Flags) {
  Bytes = Bytes ? Bytes : 16;
  // A device that keeps its buffers in host memory (PoCL's CPU device) allocates them lazily,
  // at their first use, and aborts the process (an assertion in PoCL) when that allocation
  // fails. So check first that the host's address space holds this buffer (reserved and
  // released at once: nothing is touched), and then make its first use at once (below): the
  // others were allocated when they were made, and no host allocation between the check and a
  // later first use (a render's temporaries) can take its room (that was SIGABRT at a first
  // launch, under `ulimit -v` 1.4 GB at 1000x1000).
  // A buffer above the device's per-buffer limit is refused by the driver below, with the limits.
  const bool HostMemory = Device.getInfo<CL_DEVICE_HOST_UNIFIED_MEMORY>() &&
                          Bytes <= Device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
  if (HostMemory) {
    size_t Total = Bytes;
    for (const auto &[Name, Size] : Memory)
      if (Name != Label)
        Total += Size;
    void *Probe = std::malloc(Bytes);
    if (!Probe)
      throw Error("out of memory while allocating " + Label + " (" + std::to_string(Bytes) +
                  " bytes; " + std::to_string(Total) + " bytes of buffers in all on '" +
                  DeviceName + "', which keeps them in host memory)");
    std::free(Probe);
  }
  try {
    cl::Buffer B(Ctx, Flags, Bytes);
    if (HostMemory) {
      Queue.enqueueMigrateMemObjects({B}, CL_MIGRATE_MEM_OBJECT_CONTENT_UNDEFINED);
      Queue.finish();
    }
    Memory[Label] = Bytes;
    return B;
  } catch (const cl::Error &E) {
    // Say why: an image too large for the device fails here, on its per-pixel buffers.
    const double GiB = double(1u << 30);
    char Limits[160];
    std::snprintf(Limits, sizeof Limits,
                  " (%.1f GiB; the device allows %.1f GiB per buffer, %.1f GiB in all)",
                  double(Bytes) / GiB,
                  double(Device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>()) / GiB,
                  double(Device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>()) / GiB);
    throw Error("cannot allocate " + std::to_string(Bytes) + " bytes for " + Label + " on '" +
                DeviceName + "': " + clErrorName(E.err()) + Limits);
  }
}

cl::Buffer ClContext::allocateWith(const std::string &Label, const void *Data, size_t Bytes,
                                   cl_mem_flags Flags) {
  cl::Buffer B = allocate(Label, Bytes, Flags);
  if (Bytes)
    write(B, Data, Bytes);
  return B;
}

void ClContext::write(const cl::Buffer &B, const void *Data, size_t Bytes, size_t Offset) {
  if (Bytes)
    Queue.enqueueWriteBuffer(B, CL_TRUE, Offset, Bytes, Data);
}

void ClContext::read(const cl::Buffer &B, void *Data, size_t Bytes, size_t Offset) {
  if (Bytes)
    Queue.enqueueReadBuffer(B, CL_TRUE, Offset, Bytes, Data);
}

void ClContext::launch(cl::Kernel &K, size_t GlobalSize, const std::string &TimingName) {
  if (GlobalSize == 0)
    return;
  const size_t Group = 64;
  size_t Rounded = (GlobalSize + Group - 1) / Group * Group;
  cl::Event Ev;
  try {
    Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(Rounded), cl::NDRange(Group),
                               nullptr, &Ev);
  } catch (const cl::Error &E) {
    throw Error("launching kernel '" + TimingName + "' failed: " + clErrorName(E.err()));
  }
  PendingEvents.push_back({Ev, TimingName, GlobalSize});
  if (PendingEvents.size() > 256)
    finish();
}

void ClContext::finish() {
  Queue.finish();
  for (auto &P : PendingEvents) {
    cl_ulong Start = P.Ev.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    cl_ulong End = P.Ev.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    KernelTiming &T = Timings[P.Name];
    T.Launches += 1;
    T.Seconds += (End - Start) * 1e-9;
    T.WorkItems += P.WorkItems;
  }
  PendingEvents.clear();
}

size_t ClContext::memoryTotal() const {
  size_t T = 0;
  for (auto &M : Memory)
    T += M.second;
  return T;
}

} // namespace texrender
