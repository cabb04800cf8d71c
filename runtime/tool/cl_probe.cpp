// texcc-cl-probe: prints one line per OpenCL device; exits 1 when there is none.
//
// texcc-cl-probe --time-build DIR [--variant OPTS]... [--reps N] [--hits N] [--device N]
//                [--include DIR] [--only shape|interp]
// times, on one device and in one process, what a texture program of a texcc output folder
// costs texrender before its first frame and per hit: for the shape kernel (kernel.source) and,
// when the folder has one, its interp fallback, under each variant (extra build options
// appended to texrender's "-cl-std=CL1.2 -I DIR"; default: none and -cl-opt-disable),
// interleaved, N rounds: clBuildProgram from source, the first launch (PoCL compiles the
// work-group function there; the renderer's 64-wide groups, numHits 0), and the device time per
// hit over H random hits (texcc_uniforms run first, as texrender does). Outputs of every
// variant are compared with the first variant's (largest absolute difference), and the binary
// taken after those launches is loaded into a new program and launched (PoCL's binaries carry
// the compiled work-group functions). The compiler is primed first (a tiny build), as
// texrender --watch does. Run it with POCL_KERNEL_CACHE=0, or PoCL's own cache turns every
// round after the first into a load.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>

#include "../../kernels/common/texcc_abi.h"
#include "texcc/Kernel/Manifest.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

/// Every device of every platform, in the order texrender numbers them (--device), with its
/// platform; a platform whose devices cannot be listed is skipped.
std::vector<std::pair<cl::Device, cl::Platform>> allDevices() {
  std::vector<cl::Platform> Platforms;
  try {
    cl::Platform::get(&Platforms);
  } catch (const cl::Error &) {
    Platforms.clear();
  }
  std::vector<std::pair<cl::Device, cl::Platform>> All;
  for (auto &P : Platforms) {
    std::vector<cl::Device> Devices;
    try {
      P.getDevices(CL_DEVICE_TYPE_ALL, &Devices);
    } catch (const cl::Error &) {
      continue;
    }
    for (auto &D : Devices)
      All.emplace_back(D, P);
  }
  return All;
}

int listDevices() {
  std::vector<cl::Platform> Platforms;
  try {
    cl::Platform::get(&Platforms);
  } catch (const cl::Error &) {
    Platforms.clear();
  }
  if (Platforms.empty()) {
    std::fprintf(stderr, "texcc-cl-probe: no OpenCL platform found\n");
    return 1;
  }
  int Count = 0;
  for (auto &[D, P] : allDevices())
    std::printf("%d: %s (%s)\n", Count++, D.getInfo<CL_DEVICE_NAME>().c_str(),
                P.getInfo<CL_PLATFORM_NAME>().c_str());
  if (Count == 0) {
    std::fprintf(stderr, "texcc-cl-probe: no OpenCL device found\n");
    return 1;
  }
  return 0;
}

[[noreturn]] void fail(const std::string &Message) {
  std::fprintf(stderr, "texcc-cl-probe: error: %s\n", Message.c_str());
  std::exit(1);
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string readFile(const std::string &Path) {
  std::ifstream In(Path, std::ios::binary);
  if (!In)
    fail(Path + ": cannot open");
  std::ostringstream S;
  S << In.rdbuf();
  return S.str();
}

struct Program {
  std::string Label, Path, Source;
  bool Uniforms = false;
};

struct Sample {
  double BuildMs = 0, LaunchMs = 0, HitNs = 0, MaxDiff = 0;
  // The program's binary (CL_PROGRAM_BINARIES after the launches) loaded into a new program:
  // clCreateProgramWithBinary + clBuildProgram, and its first launch.
  double LoadMs = 0, LoadLaunchMs = 0, BinaryKiB = 0;
};

double median(std::vector<double> V) {
  std::sort(V.begin(), V.end());
  return V.empty() ? 0 : V.size() % 2 ? V[V.size() / 2]
                                      : 0.5 * (V[V.size() / 2 - 1] + V[V.size() / 2]);
}

struct Bench {
  cl::Context Ctx;
  cl::Device Device;
  cl::CommandQueue Queue;
  std::string Entry;
  unsigned MaxOutputs = 2;
  size_t Hits = 0;
  std::vector<unsigned char> ArgsBin;
  cl::Buffer HitBuf, MatBuf, Settings, Texels, Images, Outputs, Scratch, Faults, Stack;

  void setUp(size_t NumHits, const std::string &Dir) {
    Hits = NumHits;
    std::string A = readFile(Dir + "/args.bin");
    ArgsBin.assign(A.begin(), A.end());
    std::vector<TexccHitAttrs> H(Hits);
    std::mt19937 Rng(1);
    std::uniform_real_distribution<float> U(-1.f, 1.f), U01(0.f, 1.f);
    for (TexccHitAttrs &T : H) {
      std::memset(&T, 0, sizeof T);
      float P[3] = {U(Rng), U(Rng), U(Rng)}, N[3] = {U(Rng), U(Rng), U(Rng)};
      float L = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]) + 1e-6f;
      for (int I = 0; I < 3; ++I) {
        T.worldPos.s[I] = T.objectPos.s[I] = P[I];
        T.normal.s[I] = T.geomNormal.s[I] = N[I] / L;
        T.viewDir.s[I] = N[I] / L;
      }
      T.tangent.s[0] = T.objectTangent.s[0] = 1;
      T.objectBitangent.s[1] = 1;
      T.uvAO.s[0] = U01(Rng), T.uvAO.s[1] = U01(Rng), T.uvAO.s[2] = U01(Rng);
    }
    HitBuf = cl::Buffer(Ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(TexccHitAttrs) * Hits,
                        H.data());
    std::vector<cl_int> Mat(Hits, 0);
    MatBuf = cl::Buffer(Ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(cl_int) * Hits,
                        Mat.data());
    TexccSettings S;
    std::memset(&S, 0, sizeof S);
    S.cameraPos.s[2] = 3;
    S.pixelAngle = 0.003f;
    Settings = cl::Buffer(Ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof S, &S);
    Texels = cl::Buffer(Ctx, CL_MEM_READ_ONLY, 64);
    Images = cl::Buffer(Ctx, CL_MEM_READ_ONLY, 64);
    Outputs = cl::Buffer(Ctx, CL_MEM_READ_WRITE, sizeof(cl_float4) * MaxOutputs * Hits);
    Scratch = cl::Buffer(Ctx, CL_MEM_READ_WRITE, 64);
    Faults = cl::Buffer(Ctx, CL_MEM_READ_WRITE, sizeof(cl_int) * TEXCC_FAULT_WORDS);
    Stack = cl::Buffer(Ctx, CL_MEM_READ_WRITE, ArgsBin.size());
  }

  void setArgs(cl::Kernel &K, int NumHits) {
    K.setArg(0, HitBuf), K.setArg(1, MatBuf), K.setArg(2, cl_int(NumHits)), K.setArg(3, Stack);
    K.setArg(4, Settings), K.setArg(5, Texels), K.setArg(6, Images), K.setArg(7, Outputs);
    K.setArg(8, Scratch), K.setArg(9, Faults);
  }

  /// Build, first launch, per-hit time and outputs of one program under Options.
  Sample run(const Program &P, const std::string &Options, std::vector<float> &Out) {
    Sample S;
    double T0 = now();
    cl::Program Prog(Ctx, P.Source);
    try {
      Prog.build({Device}, Options.c_str());
    } catch (const cl::Error &) {
      fail(P.Path + ": build failed with '" + Options + "':\n" +
           Prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(Device));
    }
    double T1 = now();
    cl::Kernel K(Prog, Entry.c_str());
    cl::Kernel Uni;
    if (P.Uniforms)
      Uni = cl::Kernel(Prog, "texcc_uniforms");
    // The first launches as texrender's warm-up makes them: 64-wide, nothing to do.
    setArgs(K, 0);
    Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
    if (P.Uniforms) {
      Uni.setArg(0, Stack), Uni.setArg(1, cl_int(0));
      Queue.enqueueNDRangeKernel(Uni, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
    }
    Queue.finish();
    double T2 = now();
    S.BuildMs = (T1 - T0) * 1000, S.LaunchMs = (T2 - T1) * 1000;
    Queue.enqueueWriteBuffer(Stack, CL_TRUE, 0, ArgsBin.size(), ArgsBin.data());
    if (P.Uniforms) {
      Uni.setArg(1, cl_int(1));
      Queue.enqueueNDRangeKernel(Uni, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
    }
    setArgs(K, int(Hits));
    const size_t Global = (Hits + 63) / 64 * 64;
    std::vector<double> PerHit;
    for (int I = 0; I < 3; ++I) {
      cl::Event Ev;
      Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(Global), cl::NDRange(64), nullptr,
                                 &Ev);
      Ev.wait();
      PerHit.push_back(double(Ev.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                              Ev.getProfilingInfo<CL_PROFILING_COMMAND_START>()) /
                       double(Hits));
    }
    S.HitNs = median(PerHit);
    {
      std::vector<std::vector<unsigned char>> Bins = Prog.getInfo<CL_PROGRAM_BINARIES>();
      S.BinaryKiB = Bins.empty() ? 0 : double(Bins[0].size()) / 1024;
      double L0 = now();
      cl::Program Loaded(Ctx, {Device}, Bins);
      Loaded.build({Device}, Options.c_str());
      double L1 = now();
      cl::Kernel LK(Loaded, Entry.c_str());
      setArgs(LK, 0);
      Queue.enqueueNDRangeKernel(LK, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
      Queue.finish();
      S.LoadMs = (L1 - L0) * 1000, S.LoadLaunchMs = (now() - L1) * 1000;
    }
    Out.resize(size_t(MaxOutputs) * 4 * Hits);
    Queue.enqueueReadBuffer(Outputs, CL_TRUE, 0, Out.size() * sizeof(float), Out.data());
    return S;
  }
};

int timeBuild(int Argc, char **Argv) {
  std::string Dir, Include;
  std::vector<std::string> Variants;
  int Reps = 5, DeviceIndex = 0;
  size_t Hits = 1 << 16;
  std::string Only;
  for (int I = 1; I < Argc; ++I) {
    std::string A = Argv[I];
    auto next = [&]() -> std::string {
      if (I + 1 >= Argc)
        fail(A + " needs a value");
      return Argv[++I];
    };
    if (A == "--time-build")
      Dir = next();
    else if (A == "--variant")
      Variants.push_back(next());
    else if (A == "--reps")
      Reps = std::atoi(next().c_str());
    else if (A == "--hits")
      Hits = size_t(std::atol(next().c_str()));
    else if (A == "--device")
      DeviceIndex = std::atoi(next().c_str());
    else if (A == "--include")
      Include = next();
    else if (A == "--only")
      Only = next();
    else
      fail("unknown option '" + A + "'");
  }
  if (Variants.empty())
    Variants = {"", "-cl-opt-disable"};
  if (Include.empty()) {
    char Buf[4096];
    ssize_t N = readlink("/proc/self/exe", Buf, sizeof Buf - 1);
    const std::string Exe = N > 0 ? std::string(Buf, size_t(N)) : std::string(".");
    Include = Exe.substr(0, Exe.rfind('/')) + "/../kernels/common";
  }
  const std::string Base = "-cl-std=CL1.2 -I " + Include;
  texcc::kernel::Manifest Layout;
  texcc::kernel::ManifestError Why;
  if (!texcc::kernel::readManifestFile(Dir + "/layout.json", Layout, Why))
    fail(Why.str());
  std::vector<Program> Programs;
  const std::string &Source = Layout.Kernel.Source;
  const std::string &Fallback = Layout.Kernel.InterpFallback;
  if (Only.empty() || Only == "shape")
    Programs.push_back({"kernel", Dir + "/" + Source, readFile(Dir + "/" + Source),
                        !Layout.Kernel.Uniforms.empty()});
  if (!Fallback.empty() && (Only.empty() || Only == "interp"))
    Programs.push_back({"interp fallback", Dir + "/" + Fallback, readFile(Dir + "/" + Fallback),
                        false});

  const auto All = allDevices();
  if (DeviceIndex < 0 || DeviceIndex >= int(All.size()))
    fail("no OpenCL device " + std::to_string(DeviceIndex));
  Bench B;
  B.Device = All[size_t(DeviceIndex)].first;
  B.Ctx = cl::Context(B.Device);
  B.Queue = cl::CommandQueue(B.Ctx, B.Device, CL_QUEUE_PROFILING_ENABLE);
  B.Entry = Layout.Kernel.Entry;
  B.setUp(Hits, Dir);
  {
    double T0 = now();
    cl::Program Prime(B.Ctx, "kernel void prime(global int *o) { o[0] = 1; }");
    Prime.build({B.Device}, Base.c_str());
    std::printf("compiler primed in %.1f ms\n", (now() - T0) * 1000);
  }
  // Samples[program][variant]
  std::vector<std::vector<std::vector<Sample>>> Samples(
      Programs.size(), std::vector<std::vector<Sample>>(Variants.size()));
  for (int Rep = 0; Rep < Reps; ++Rep)
    for (size_t P = 0; P < Programs.size(); ++P) {
      std::vector<float> Reference;
      for (size_t Step = 0; Step < Variants.size(); ++Step) {
        // Interleaved, and the order rotates with the round.
        size_t V = (Step + size_t(Rep)) % Variants.size();
        std::vector<float> Out;
        Sample S = B.run(Programs[P], Base + (Variants[V].empty() ? "" : " " + Variants[V]), Out);
        if (V == 0)
          Reference = Out;
        Samples[P][V].push_back(S);
        if (V != 0 && !Reference.empty())
          for (size_t I = 0; I < Out.size(); ++I)
            Samples[P][V].back().MaxDiff =
                std::max(Samples[P][V].back().MaxDiff, double(std::fabs(Out[I] - Reference[I])));
        std::printf("round %d, %s, '%s': build %.1f ms, first launch %.1f ms, %.1f ns per hit; "
                    "its binary (%.0f KiB) loaded in %.1f ms, first launch %.1f ms\n",
                    Rep + 1, Programs[P].Label.c_str(), Variants[V].c_str(), S.BuildMs, S.LaunchMs,
                    S.HitNs, S.BinaryKiB, S.LoadMs, S.LoadLaunchMs);
        std::fflush(stdout);
      }
    }
  std::printf("medians of %d rounds (%zu hits):\n", Reps, Hits);
  for (size_t P = 0; P < Programs.size(); ++P)
    for (size_t V = 0; V < Variants.size(); ++V) {
      std::vector<double> Build, Launch, Sum, Hit, Diff, Load;
      for (const Sample &S : Samples[P][V]) {
        Load.push_back(S.LoadMs + S.LoadLaunchMs);
        Build.push_back(S.BuildMs), Launch.push_back(S.LaunchMs);
        Sum.push_back(S.BuildMs + S.LaunchMs), Hit.push_back(S.HitNs);
        Diff.push_back(S.MaxDiff);
      }
      std::printf("%s, '%s': build %.1f ms + first launch %.1f ms = %.1f ms (median of the "
                  "sums), %.1f ns per hit",
                  Programs[P].Label.c_str(), Variants[V].c_str(), median(Build), median(Launch),
                  median(Sum), median(Hit));
      std::printf("; its binary loaded + first launch %.1f ms", median(Load));
      if (V != 0)
        std::printf(", outputs differ from '%s' by at most %g", Variants[0].c_str(),
                    *std::max_element(Diff.begin(), Diff.end()));
      std::printf("\n");
    }
  return 0;
}

} // namespace

int main(int Argc, char **Argv) {
  if (Argc == 1)
    return listDevices();
  try {
    return timeBuild(Argc, Argv);
  } catch (const cl::Error &E) {
    fail(std::string("OpenCL call ") + E.what() + " failed (" + std::to_string(E.err()) + ")");
  }
}
