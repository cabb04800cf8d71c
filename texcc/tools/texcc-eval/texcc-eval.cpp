// texcc-eval: evaluates the textures of a texcc output folder at N deterministic pseudo-random
// hit points for every material, and prints one line per (hit, material, output):
//   <hit> <material> <output> <x> <y> <z> <w>        (%.9g)
// On the first OpenCL device it builds OUTDIR/proctex.cl and runs the kernel(s) as layout.json
// says (wavefront: every launch in order, then the outputs kernel); with --host it compiles
// OUTDIR/proctex.cpp with g++ (-O1 -shared) and calls texcc_host_evaluate through dlopen.
// Images bound in layout.json are replaced by small synthetic ones (deterministic, the same in
// both paths), so that no image loader is needed; --texels FILE gives image I's texels instead
// (the Blender conformance fixtures' images: testsuite/Inputs/blender/compare.py).
// With --time R and one or more folders of one graph (modes, options), it prints instead the
// texture kernels' device time per textured hit of each, over R rounds in one process
// (timeOpenCL): the per-hit figure of bench/per_hit.py that the machine's load does not swamp.
#include "texcc_abi.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/File.h"
#include "texcc/Kernel/TextureFault.h"

#include <CL/opencl.hpp>
#include "texcc/Kernel/Manifest.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using Json = nlohmann::json;

namespace {

struct Options {
  std::string OutDir;                // the first of OutDirs
  std::vector<std::string> OutDirs;  // several only with --time
  unsigned TimeReps = 0;             // --time R
  unsigned Grid = 16;
  uint64_t Seed = 1;
  bool Host = false;
  std::vector<cl_float4> Points;     // --points FILE: hit I's ObjectPos and WorldPos
  /// --texels FILE (repeatable): image I's texels instead of the synthetic ones, each file
  /// "W H FLAGS" and W x H x 4 linear RGBA numbers, row 0 at the top (TexccImageInfo).
  std::vector<std::pair<TexccImageInfo, std::vector<cl_float4>>> Texels;
  /// --cl-options STR: appended to the device build's options (e.g. the kernel built as
  /// texrender's quick first build, -DTEXCC_FN=__attribute__((noinline))).
  std::string ClOptions;
};

/// Every input of one evaluation: the hits (Grid x materials), settings, synthetic images.
struct Inputs {
  std::vector<TexccHitAttrs> Hits;
  std::vector<cl_int> HitMaterial;
  TexccSettings Settings{};
  std::vector<cl_float4> Texels;
  std::vector<TexccImageInfo> Images;
};

struct LayoutInfo {
  unsigned NumMaterials = 0;
  unsigned MaxOutputs = 1;
  unsigned ScratchPerHit = 0;
  std::vector<unsigned> OutputsPerMaterial;
  std::vector<std::string> Launches; // wavefront node kernels, in order
  std::string Entry;
  std::string Uniforms;              // shape mode: texcc_uniforms, run once before Entry
  unsigned NumImages = 0;
};

[[noreturn]] void die(const std::string &Message) {
  std::cerr << "texcc-eval: error: " << Message << "\n";
  std::exit(1);
}

std::string readFile(const std::string &Path) {
  std::string Text, Why;
  if (!texcc::readRegularFile(Path, Text, Why))
    die("cannot read '" + Path + "': " + Why);
  return Text;
}

/// splitmix64: a small, portable, deterministic generator.
struct Rng {
  uint64_t State;
  uint64_t next() {
    uint64_t Z = (State += 0x9E3779B97F4A7C15ull);
    Z = (Z ^ (Z >> 30)) * 0xBF58476D1CE4E5B9ull;
    Z = (Z ^ (Z >> 27)) * 0x94D049BB133111EBull;
    return Z ^ (Z >> 31);
  }
  float uniform(float Lo, float Hi) {
    return Lo + (Hi - Lo) * static_cast<float>(next() >> 40) / static_cast<float>(1 << 24);
  }
};

cl_float4 f4(float X, float Y, float Z, float W) {
  cl_float4 V;
  V.s[0] = X;
  V.s[1] = Y;
  V.s[2] = Z;
  V.s[3] = W;
  return V;
}

cl_float4 unitVector(const cl_float4 &V) {
  const float L = std::sqrt(V.s[0] * V.s[0] + V.s[1] * V.s[1] + V.s[2] * V.s[2]);
  return f4(V.s[0] / L, V.s[1] / L, V.s[2] / L, 0.0f);
}

cl_float4 unitVector(Rng &R) {
  for (;;) {
    float X = R.uniform(-1, 1), Y = R.uniform(-1, 1), Z = R.uniform(-1, 1);
    float L = std::sqrt(X * X + Y * Y + Z * Z);
    if (L > 0.1f && L <= 1.0f)
      return f4(X / L, Y / L, Z / L, 0.0f);
  }
}

TexccHitAttrs randomHit(Rng &R) {
  TexccHitAttrs H{};
  H.worldPos = f4(R.uniform(-3, 3), R.uniform(-3, 3), R.uniform(-3, 3), 1.0f);
  H.objectPos = f4(R.uniform(-1, 1), R.uniform(-1, 1), R.uniform(-1, 1), 1.0f);
  H.normal = unitVector(R);
  // A geometric normal within 37 degrees of the shading normal, as on a mesh (bump's offsets
  // lie across it).
  const cl_float4 Off = unitVector(R);
  H.geomNormal = unitVector(f4(H.normal.s[0] + 0.6f * Off.s[0], H.normal.s[1] + 0.6f * Off.s[1],
                               H.normal.s[2] + 0.6f * Off.s[2], 0.0f));
  H.tangent = unitVector(R);
  H.viewDir = unitVector(R);
  H.uvAO = f4(R.uniform(-0.5f, 1.5f), R.uniform(-0.5f, 1.5f), R.uniform(0, 1), 0.0f);
  // TangentSign and Backfacing from draws already made (the stream of earlier draws stays).
  H.tangent.s[3] = H.viewDir.s[0] >= 0 ? 1.0f : -1.0f;
  H.uvAO.s[3] = H.viewDir.s[1] >= 0 ? 1.0f : 0.0f;
  return H;
}

LayoutInfo readLayout(const std::string &OutDir) {
  texcc::kernel::Manifest L;
  texcc::kernel::ManifestError Why;
  if (!texcc::kernel::readManifestFile(OutDir + "/layout.json", L, Why))
    die(Why.str());
  LayoutInfo Info;
  Info.MaxOutputs = L.MaxOutputs;
  Info.ScratchPerHit = L.ScratchFloat4PerHit;
  for (const texcc::kernel::MaterialLayout &M : L.Materials)
    Info.OutputsPerMaterial.push_back(static_cast<unsigned>(M.Outputs.size()));
  Info.NumMaterials = static_cast<unsigned>(Info.OutputsPerMaterial.size());
  Info.Entry = L.Kernel.Entry;
  Info.Uniforms = L.Kernel.Uniforms;
  for (const texcc::kernel::LaunchLayout &Launch : L.Kernel.Launches)
    Info.Launches.push_back(Launch.Kernel);
  Info.NumImages = static_cast<unsigned>(L.Images.size());
  return Info;
}

Inputs makeInputs(const LayoutInfo &Info, const Options &Opts) {
  Inputs In;
  Rng R{Opts.Seed * 0x2545F4914F6CDD1Dull + 17};
  for (unsigned I = 0; I < Opts.Grid; ++I) {
    TexccHitAttrs H = randomHit(R);
    if (!Opts.Points.empty())
      H.objectPos = H.worldPos = Opts.Points[I];
    for (unsigned M = 0; M < Info.NumMaterials; ++M) {
      In.Hits.push_back(H);
      In.HitMaterial.push_back(Info.OutputsPerMaterial[M] ? static_cast<cl_int>(M) : -1);
    }
  }
  In.Settings.cameraPos = f4(0.5f, 1.5f, -2.0f, 0.0f);
  In.Settings.time = 0.75f;
  In.Settings.frame = 3;
  In.Settings.pixelAngle = 2.8e-3f; // a 256-pixel 40-degree view: bump steps of 2.8e-4 rad
  for (unsigned K = 0; K < Info.NumImages; ++K) {
    if (K < Opts.Texels.size()) {
      TexccImageInfo Im = Opts.Texels[K].first;
      Im.offset = static_cast<int>(In.Texels.size());
      In.Texels.insert(In.Texels.end(), Opts.Texels[K].second.begin(), Opts.Texels[K].second.end());
      In.Images.push_back(Im);
      continue;
    }
    TexccImageInfo Im{};
    Im.offset = static_cast<int>(In.Texels.size());
    Im.width = 4 + 3 * static_cast<int>(K);
    Im.height = 3 + 2 * static_cast<int>(K);
    for (int T = 0; T < Im.width * Im.height; ++T)
      In.Texels.push_back(f4(R.uniform(0, 1), R.uniform(0, 1), R.uniform(0, 1), 1.0f));
    In.Images.push_back(Im);
  }
  return In;
}

void printOutputs(const LayoutInfo &Info, const Options &Opts, const std::vector<float> &Out) {
  for (unsigned I = 0; I < Opts.Grid; ++I)
    for (unsigned M = 0; M < Info.NumMaterials; ++M) {
      size_t Hit = static_cast<size_t>(I) * Info.NumMaterials + M;
      for (unsigned K = 0; K < Info.OutputsPerMaterial[M]; ++K) {
        const float *V = &Out[(Hit * Info.MaxOutputs + K) * 4];
        std::printf("%u %u %u %.9g %.9g %.9g %.9g\n", I, M, K, V[0], V[1], V[2], V[3]);
      }
    }
}

/// A texture's fault (a loop past its budget, a __global array read out of bounds:
/// docs/reliability.md "User code"), F the fault record, at hit Hit: one line naming the node,
/// its line and the grid point, as texrender names the pixel; exit 1, no values printed.
[[noreturn]] void dieOfFault(const Options &Opts, const LayoutInfo &Info, const cl_int *F,
                             size_t Hit) {
  std::string ArgsBin, Why; // without it, an instruction's node is "?"
  texcc::readRegularFile(Opts.OutDir + "/args.bin", ArgsBin, Why);
  texcc::kernel::Manifest M; // read again on this error path only; "?" names if it fails
  texcc::kernel::ManifestError ManifestWhy;
  texcc::kernel::readManifestFile(Opts.OutDir + "/layout.json", M, ManifestWhy);
  die(texcc::describeTextureFault(F, M, ArgsBin) +
      " at grid point " + std::to_string(Hit / std::max(Info.NumMaterials, 1u)));
}

template <class T> std::vector<T> nonEmpty(std::vector<T> V) {
  if (V.empty())
    V.resize(1);
  return V;
}

cl::Device firstDevice() {
  std::vector<cl::Platform> Platforms;
  cl::Platform::get(&Platforms);
  for (cl::Platform &P : Platforms) {
    std::vector<cl::Device> D;
    P.getDevices(CL_DEVICE_TYPE_ALL, &D);
    if (!D.empty())
      return D.front();
  }
  die("no OpenCL device found");
}

/// One texcc output folder on the device: its program built, its buffers (the inputs shared by
/// every folder of one graph), its kernels with their arguments set, texcc_uniforms run.
struct DeviceRun {
  DeviceRun(const cl::Context &Ctx, const cl::Device &Dev, cl::CommandQueue &Q,
            const std::string &OutDir, const LayoutInfo &Info, const Inputs &In,
            const std::string &ClOptions)
      : Info(Info), NumHits(In.Hits.size()) {
    cl::Program Prog(Ctx, readFile(OutDir + "/proctex.cl"));
    try {
      Prog.build({Dev}, ("-cl-std=CL1.2 " + ClOptions).c_str());
    } catch (const cl::Error &) {
      die("building " + OutDir + "/proctex.cl on '" + Dev.getInfo<CL_DEVICE_NAME>() +
          "' failed:\n" + Prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(Dev));
    }
    std::string Args = readFile(OutDir + "/args.bin");
    std::vector<cl_uint> Words((Args.size() + 3) / 4 + 1, 0);
    std::memcpy(Words.data(), Args.data(), Args.size());
    auto buffer = [&](auto Vec, cl_mem_flags Flags) {
      auto V = nonEmpty(Vec);
      using T = typename decltype(V)::value_type;
      return cl::Buffer(Ctx, Flags | CL_MEM_COPY_HOST_PTR, V.size() * sizeof(T), V.data());
    };
    cl::Buffer Hits = buffer(In.Hits, CL_MEM_READ_ONLY);
    cl::Buffer HitMaterial = buffer(In.HitMaterial, CL_MEM_READ_ONLY);
    cl::Buffer FakeStack = buffer(Words, CL_MEM_READ_WRITE); // texcc_uniforms writes into it
    cl::Buffer Settings = buffer(std::vector<TexccSettings>{In.Settings}, CL_MEM_READ_ONLY);
    cl::Buffer Texels = buffer(In.Texels, CL_MEM_READ_ONLY);
    cl::Buffer Images = buffer(In.Images, CL_MEM_READ_ONLY);
    Outputs = buffer(std::vector<float>(NumHits * Info.MaxOutputs * 4, 0.0f), CL_MEM_READ_WRITE);
    cl::Buffer Scratch =
        buffer(std::vector<cl_float4>(NumHits * Info.ScratchPerHit), CL_MEM_READ_WRITE);
    cl::Buffer Faults = buffer(std::vector<cl_int>(TEXCC_FAULT_WORDS, 0), CL_MEM_READ_WRITE);
    auto kernel = [&](const std::string &Name) {
      try {
        return cl::Kernel(Prog, Name.c_str());
      } catch (const cl::Error &) {
        die(OutDir + "/proctex.cl: no kernel '" + Name + "' (layout.json names it)");
      }
    };
    if (!Info.Uniforms.empty()) {
      // Shape mode's hoisted values, computed into fakeStack once, as the runtime does.
      cl::Kernel U = kernel(Info.Uniforms);
      U.setArg(0, FakeStack);
      U.setArg(1, static_cast<cl_int>(Info.NumMaterials));
      Q.enqueueNDRangeKernel(U, cl::NullRange, cl::NDRange(1), cl::NullRange);
    }
    std::vector<std::string> Names = Info.Launches;
    Names.push_back(Info.Entry);
    for (const std::string &Name : Names) {
      cl::Kernel K = kernel(Name);
      K.setArg(0, Hits);
      K.setArg(1, HitMaterial);
      K.setArg(2, static_cast<cl_int>(NumHits));
      K.setArg(3, FakeStack);
      K.setArg(4, Settings);
      K.setArg(5, Texels);
      K.setArg(6, Images);
      K.setArg(7, Outputs);
      K.setArg(8, Scratch);
      if (K.getInfo<CL_KERNEL_NUM_ARGS>() > 9) // the fault record (docs/abi.md)
        K.setArg(9, Faults);
      Kernels.push_back(K);
    }
    // A kernel does not retain its buffer arguments: the run owns them.
    Buffers = {Hits, HitMaterial, FakeStack, Settings, Texels, Images, Scratch, Faults};
  }

  /// Enqueues every texture kernel once over all hits; their events go to Events.
  void enqueue(cl::CommandQueue &Q, std::vector<cl::Event> *Events = nullptr) {
    for (cl::Kernel &K : Kernels) {
      if (!NumHits)
        continue;
      // Work-groups of 64, over a multiple of 64 items, as texrender launches them (abi.md).
      cl::Event E;
      const size_t Global = (NumHits + WorkGroup - 1) / WorkGroup * WorkGroup;
      Q.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(Global), cl::NDRange(WorkGroup),
                             nullptr, &E);
      if (Events)
        Events->push_back(E);
    }
  }

  /// The launches' fault record (all zero: no fault).
  std::vector<cl_int> faults(cl::CommandQueue &Q) {
    std::vector<cl_int> F(TEXCC_FAULT_WORDS, 0);
    Q.enqueueReadBuffer(Buffers.back(), CL_TRUE, 0, F.size() * sizeof(cl_int), F.data());
    return F;
  }

  std::vector<float> read(cl::CommandQueue &Q) {
    std::vector<float> Out(NumHits * Info.MaxOutputs * 4, 0.0f);
    Q.enqueueReadBuffer(Outputs, CL_TRUE, 0, Out.size() * sizeof(float), Out.data());
    return Out;
  }

  static constexpr size_t WorkGroup = 64;
  LayoutInfo Info;
  size_t NumHits;
  cl::Buffer Outputs;
  std::vector<cl::Buffer> Buffers;
  std::vector<cl::Kernel> Kernels;
};

std::vector<float> runOpenCL(const LayoutInfo &Info, const Inputs &In, const Options &Opts) {
  cl::Device Dev = firstDevice();
  cl::Context Ctx(Dev);
  cl::CommandQueue Q(Ctx, Dev);
  DeviceRun Run(Ctx, Dev, Q, Opts.OutDir, Info, In, Opts.ClOptions);
  Run.enqueue(Q);
  std::vector<float> Out = Run.read(Q);
  if (const std::vector<cl_int> F = Run.faults(Q); F[TEXCC_FAULT_KIND] != TEXCC_FAULT_NONE)
    dieOfFault(Opts, Info, F.data(), size_t(F[TEXCC_FAULT_HIT]));
  return Out;
}

double median(std::vector<double> V) {
  std::sort(V.begin(), V.end());
  return V.empty() ? 0.0 : (V[(V.size() - 1) / 2] + V[V.size() / 2]) / 2;
}

/// --time R: the texture kernels of every folder (one graph, several modes or options) over the
/// same hits, in one process on one queue: one untimed warm-up each (PoCL compiles the
/// work-group function at the first launch), then R rounds that launch every folder once, in
/// an order that rotates with the round. Device time from the profiling events, per hit;
/// ratios to the first folder are taken within each round, so that the load of the machine,
/// which drifts between rounds, cancels. Prints one JSON object.
void timeOpenCL(const Options &Opts) {
  cl::Device Dev = firstDevice();
  cl::Context Ctx(Dev);
  cl::CommandQueue Q(Ctx, Dev, CL_QUEUE_PROFILING_ENABLE);
  const LayoutInfo First = readLayout(Opts.OutDirs.front());
  const Inputs In = makeInputs(First, Opts);
  std::vector<std::unique_ptr<DeviceRun>> Runs;
  for (const std::string &Dir : Opts.OutDirs) {
    LayoutInfo Info = readLayout(Dir);
    if (Info.OutputsPerMaterial != First.OutputsPerMaterial || Info.NumImages != First.NumImages)
      die(Dir + ": not the materials of " + Opts.OutDirs.front() + " (time folders of one graph)");
    Runs.push_back(std::make_unique<DeviceRun>(Ctx, Dev, Q, Dir, Info, In, Opts.ClOptions));
    Runs.back()->enqueue(Q);
    Q.finish();
  }
  size_t Textured = 0;
  for (cl_int M : In.HitMaterial)
    Textured += M >= 0;
  const size_t N = Runs.size();
  std::vector<std::vector<double>> NsPerHit(N), Ratios(N);
  for (unsigned Round = 0; Round < Opts.TimeReps; ++Round) {
    std::vector<double> This(N);
    for (size_t J = 0; J < N; ++J) {
      const size_t I = (J + Round) % N;
      std::vector<cl::Event> Events;
      Runs[I]->enqueue(Q, &Events);
      Q.finish();
      double Ns = 0;
      for (cl::Event &E : Events)
        Ns += double(E.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                     E.getProfilingInfo<CL_PROFILING_COMMAND_START>());
      This[I] = Ns / double(Textured ? Textured : 1);
    }
    for (size_t I = 0; I < N; ++I) {
      NsPerHit[I].push_back(This[I]);
      Ratios[I].push_back(This[I] / This[0]);
    }
  }
  Json Out = {{"device", Dev.getInfo<CL_DEVICE_NAME>()}, {"texturedHits", Textured},
              {"rounds", Opts.TimeReps}, {"folders", Json::array()}};
  for (size_t I = 0; I < N; ++I)
    Out["folders"].push_back({{"folder", Opts.OutDirs[I]},
                              {"nsPerHit", NsPerHit[I]},
                              {"medianNsPerHit", median(NsPerHit[I])},
                              {"minNsPerHit", *std::min_element(NsPerHit[I].begin(), NsPerHit[I].end())},
                              {"medianRatioToFirst", median(Ratios[I])}});
  std::cout << Out.dump(1) << "\n";
}

using HostEntry = int (*)(int, const TexccHitAttrs *, const TexccSettings *, const cl_float4 *,
                          const TexccImageInfo *, float *);

std::vector<float> runHost(const LayoutInfo &Info, const Inputs &In, const Options &Opts) {
  char Dir[] = "/tmp/texcc-eval-XXXXXX";
  if (!mkdtemp(Dir))
    die("cannot create a temporary folder");
  std::string So = std::string(Dir) + "/proctex.so";
  const char *Cxx = std::getenv("CXX");
  std::string Cmd = std::string(Cxx && *Cxx ? Cxx : "g++") +
                    " -std=gnu++17 -O1 -shared -fPIC -w -o '" + So + "' '" + Opts.OutDir +
                    "/proctex.cpp'";
  if (std::system(Cmd.c_str()) != 0)
    die("compiling proctex.cpp failed: " + Cmd);
  void *Lib = dlopen(So.c_str(), RTLD_NOW | RTLD_LOCAL);
  std::remove(So.c_str());
  rmdir(Dir);
  if (!Lib)
    die(std::string("dlopen: ") + dlerror());
  auto Fn = reinterpret_cast<HostEntry>(dlsym(Lib, Info.Entry.c_str()));
  if (!Fn)
    die("proctex.cpp has no '" + Info.Entry + "'");
  // The prelude's fault record (HostPrelude.hpp); a proctex.cpp of an older texcc has none.
  auto *Faults = static_cast<cl_int *>(dlsym(Lib, "texcc_host_faults"));
  std::vector<float> Out(In.Hits.size() * Info.MaxOutputs * 4, 0.0f);
  auto Texels = nonEmpty(In.Texels);
  auto Images = nonEmpty(In.Images);
  for (size_t H = 0; H < In.Hits.size(); ++H) {
    if (In.HitMaterial[H] < 0)
      continue;
    Fn(In.HitMaterial[H], &In.Hits[H], &In.Settings, Texels.data(), Images.data(),
       &Out[H * Info.MaxOutputs * 4]);
    if (Faults && Faults[TEXCC_FAULT_KIND] != TEXCC_FAULT_NONE)
      dieOfFault(Opts, Info, Faults, H);
  }
  return Out;
}

Options parseArgs(int Argc, char **Argv) {
  Options Opts;
  for (int I = 1; I < Argc; ++I) {
    std::string A = Argv[I];
    auto value = [&]() -> std::string {
      if (I + 1 >= Argc)
        die("missing value after " + A);
      return Argv[++I];
    };
    if (A == "--grid")
      Opts.Grid = static_cast<unsigned>(std::stoul(value()));
    else if (A == "--seed")
      Opts.Seed = std::stoull(value());
    else if (A == "--host")
      Opts.Host = true;
    else if (A == "--points") {
      // One "x y z" per line; the grid becomes one hit per point, other attributes random.
      std::istringstream In(readFile(value()));
      float X, Y, Z;
      while (In >> X >> Y >> Z)
        Opts.Points.push_back(f4(X, Y, Z, 1.0f));
      if (!In.eof() || Opts.Points.empty())
        die("--points: expected lines of three numbers");
    }
    else if (A == "--texels") {
      std::istringstream In(readFile(value()));
      TexccImageInfo Im{};
      std::vector<cl_float4> T;
      float V[4];
      if (!(In >> Im.width >> Im.height >> Im.flags) || Im.width <= 0 || Im.height <= 0)
        die("--texels: expected 'WIDTH HEIGHT FLAGS' first");
      while (In >> V[0] >> V[1] >> V[2] >> V[3])
        T.push_back(f4(V[0], V[1], V[2], V[3]));
      if (!In.eof() || T.size() != size_t(Im.width) * size_t(Im.height))
        die("--texels: expected WIDTH x HEIGHT texels of four numbers");
      Opts.Texels.emplace_back(Im, std::move(T));
    }
    else if (A == "--cl-options")
      Opts.ClOptions = value();
    else if (A == "--time")
      Opts.TimeReps = static_cast<unsigned>(std::stoul(value()));
    else if (A == "--help" || A == "-h") {
      std::cout << "usage: texcc-eval OUTDIR [--grid N | --points FILE] [--seed S] [--host] [--texels FILE]...\n"
                   "                  [--cl-options STR]\n"
                   "       texcc-eval OUTDIR [OUTDIR ...] --time R [--grid N] [--seed S] [--cl-options STR]\n";
      std::exit(0);
    } else if (!A.empty() && A[0] == '-')
      die("unknown option '" + A + "'");
    else
      Opts.OutDirs.push_back(A);
  }
  if (!Opts.Points.empty())
    Opts.Grid = static_cast<unsigned>(Opts.Points.size());
  if (!Opts.OutDirs.empty())
    Opts.OutDir = Opts.OutDirs.front();
  if (Opts.OutDirs.size() > 1 && !Opts.TimeReps)
    die("several texcc output folders are for --time only");
  if (Opts.TimeReps && Opts.Host)
    die("--time measures the OpenCL kernels, not --host");
  if (!Opts.ClOptions.empty() && Opts.Host)
    die("--cl-options is for the OpenCL build, not --host");
  if (Opts.OutDir.empty())
    die("no texcc output folder given (usage: texcc-eval OUTDIR [--grid N] [--seed S] "
        "[--host])");
  return Opts;
}

} // namespace

int main(int Argc, char **Argv) {
  // Out of memory: one line naming the step, exit status 1 (texcc/OutOfMemory.h).
  texcc::installOutOfMemoryHandler("texcc-eval");
  Options Opts = parseArgs(Argc, Argv);
  try {
    if (Opts.TimeReps) {
      timeOpenCL(Opts);
      return 0;
    }
    LayoutInfo Info =
        texcc::whileAllocating("reading layout.json", [&] { return readLayout(Opts.OutDir); });
    Inputs In = texcc::whileAllocating("making the hits", [&] { return makeInputs(Info, Opts); });
    std::vector<float> Out = texcc::whileAllocating("evaluating the textures", [&] {
      return Opts.Host ? runHost(Info, In, Opts) : runOpenCL(Info, In, Opts);
    });
    printOutputs(Info, Opts, Out);
  } catch (const std::bad_alloc &E) {
    texcc::reportOutOfMemory("texcc-eval", E);
    return 1;
  } catch (const cl::Error &E) {
    die(std::string("OpenCL: ") + E.what() + " (" + std::to_string(E.err()) + ")");
  } catch (const std::exception &E) {
    die(E.what());
  }
  return 0;
}
