#include "texrender/TextureTiers.h"
#include "texrender/Error.h"
#include "texrender/Image.h"

#include "texcc_abi.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace texrender {

namespace {
/// The --tier policies by name: the tiers of a shape-mode layout, plus auto.
const std::pair<TierPolicy, const char *> TierPolicies[] = {
    {TierPolicy::Auto, "auto"},
    {TierPolicy::Interp, FallbackTierName},
    {TierPolicy::Shape, ShapeTierName},
};
} // namespace

TierPolicy parseTierPolicy(const std::string &Name) {
  for (const auto &[P, N] : TierPolicies)
    if (Name == N)
      return P;
  throw Error("--tier: unknown tier policy '" + Name + "' (expected auto, interp or shape)");
}

const char *tierPolicyName(TierPolicy P) {
  for (const auto &[Q, N] : TierPolicies)
    if (P == Q)
      return N;
  return "auto";
}

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string readKernelSource(const std::string &Path) {
  return readWholeFile(Path, " kernel source");
}

namespace {

bool isIdentChar(char C) { return std::isalnum(static_cast<unsigned char>(C)) || C == '_'; }

/// The word that ends just before Pos (after skipping blanks), and where it starts.
std::string wordBefore(const std::string &S, size_t &Pos) {
  while (Pos > 0 && std::isspace(static_cast<unsigned char>(S[Pos - 1])))
    --Pos;
  size_t End = Pos;
  while (Pos > 0 && isIdentChar(S[Pos - 1]))
    --Pos;
  return S.substr(Pos, End - Pos);
}

bool declaresKernel(const std::string &Source, const std::string &Name) {
  for (size_t At = Source.find(Name); At != std::string::npos; At = Source.find(Name, At + 1)) {
    size_t After = At + Name.size();
    if ((At > 0 && isIdentChar(Source[At - 1])) || (After < Source.size() && isIdentChar(Source[After])))
      continue;
    while (After < Source.size() && std::isspace(static_cast<unsigned char>(Source[After])))
      ++After;
    if (After == Source.size() || Source[After] != '(')
      continue;
    size_t Pos = At;
    if (wordBefore(Source, Pos) != "void")
      continue;
    const std::string Qualifier = wordBefore(Source, Pos);
    if (Qualifier == "kernel" || Qualifier == "__kernel")
      return true;
  }
  return false;
}

} // namespace

void requireKernelsDeclared(const std::string &File, const std::string &Source,
                            const std::vector<std::string> &Kernels) {
  for (const std::string &Name : Kernels)
    if (!declaresKernel(Source, Name))
      throw Error(File + ": no kernel '" + Name +
                  "' in the texture program (layout.json names it; the source declares none)");
}

int backgroundBuildNice() {
  static const int Nice = [] {
    const char *E = std::getenv("TEXRENDER_BUILD_NICE");
    return E && *E ? std::clamp(std::atoi(E), 0, 19) : DefaultBackgroundBuildNice;
  }();
  return Nice;
}

void lowerThisThreadsPriority(int Increment) {
  if (Increment <= 0)
    return;
  errno = 0;
  const int Own = getpriority(PRIO_PROCESS, 0); // this thread's, as inherited at its creation
  if (Own == -1 && errno != 0)
    return;
  setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), std::min(19, Own + Increment));
}

namespace {
std::atomic<double> LastInteractiveEdit{0};
} // namespace

void noteInteractiveEdit() { LastInteractiveEdit.store(steadySeconds()); }

void waitForEditPause() {
  for (;;) {
    const double Left = LastInteractiveEdit.load() + EditPauseSeconds - steadySeconds();
    if (Left <= 0)
      return;
    std::this_thread::sleep_for(std::chrono::duration<double>(Left));
  }
}

void warmUpKernels(ClContext &Cl, const cl::Program &P, const std::vector<std::string> &Kernels,
                   const std::string &File, bool Background) {
  // The renderer's work-group size: PoCL compiles per local size.
  cl::Buffer Dummy(Cl.context(), CL_MEM_READ_WRITE, sizeof(TexccHitAttrs) * 4);
  cl::CommandQueue Queue(Cl.context(), Cl.device());
  for (const std::string &Name : Kernels) {
    cl::Kernel K;
    try {
      K = cl::Kernel(P, Name.c_str());
    } catch (const cl::Error &E) {
      throw Error(File + ": no kernel '" + Name + "' in the texture program (" +
                  clErrorName(E.err()) + ")");
    }
    // Texture kernels take 9 arguments (numHits third); texcc_uniforms takes 2 (fakeStack,
    // numMaterials). A count of 0 makes every work-item return at once.
    const cl_uint Args = K.getInfo<CL_KERNEL_NUM_ARGS>();
    for (cl_uint Arg = 0; Arg < Args; ++Arg)
      if (Arg == 2 || (Args == 2 && Arg == 1))
        K.setArg(Arg, cl_int(0));
      else
        K.setArg(Arg, Dummy);
    if (Background)
      waitForEditPause();
    Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(64), cl::NDRange(64));
    if (Args != 2) { // texcc_uniforms runs one work-item
      if (Background) {
        Queue.finish();
        waitForEditPause();
      }
      Queue.enqueueNDRangeKernel(K, cl::NullRange, cl::NDRange(LargeGridItems), cl::NDRange(64));
    }
    if (Background)
      Queue.finish(); // one compile at a time, each after a pause
  }
  Queue.finish();
}

namespace {

cl::Program buildAndWarm(ClContext &Cl, const std::string &Path, const std::string &Source,
                         const std::vector<std::string> &Kernels, const std::string &Options) {
  waitForEditPause(); // PoCL's compiler holds up launches while it runs
  return Cl.buildProgram(Path, Source, Options, "", /*Background=*/true,
                         [&](const cl::Program &P) {
                           warmUpKernels(Cl, P, Kernels, Path, /*Background=*/true);
                         });
}

} // namespace

std::string stackHeadroomOption(const Layout &L, const std::string &Source, unsigned &Capacity) {
  Capacity = L.StackSlots;
  if (L.Spill || Source.find("#ifndef TEXCC_STACK_SLOTS") == std::string::npos)
    return "";
  Capacity = std::min(L.StackLimit, std::max(2 * L.StackSlots, L.StackSlots + 4));
  Capacity = std::max(Capacity, L.StackSlots);
  return " -DTEXCC_STACK_SLOTS=" + std::to_string(Capacity);
}

namespace {

/// Builds and warms up P, a program of the job's layout L (FallbackSlots: a fallback's
/// value-stack capacity).
cl::Program buildJobProgram(ClContext &Cl, const Layout &L, const TierProgram &P,
                            const std::string &Options, unsigned &FallbackSlots) {
  if (P.Role == ProgramRole::Quick)
    throw Error("a background build job names a quick program (the quick tier warms its own)");
  const bool Primary = P.Role == ProgramRole::Primary;
  const std::string &File = Primary ? L.KernelSource : L.InterpFallback;
  const std::string Source = P.Text.empty() ? readKernelSource(File) : P.Text;
  std::vector<std::string> Kernels{L.Entry};
  std::string All = Options + P.Options;
  if (!Primary)
    All += stackHeadroomOption(L, Source, FallbackSlots);
  else if (!L.Uniforms.empty())
    Kernels.push_back(L.Uniforms);
  return buildAndWarm(Cl, File, Source, Kernels, All);
}

} // namespace

TierBuildResult buildTierJob(ClContext &Cl, const std::function<Layout()> &MakeLayout,
                             TierJob Job, const std::string &Options, double Epoch) {
  TierBuildResult R;
  R.SameLayout = Job.SameLayout;
  try {
    R.L = MakeLayout();
    for (const TierProgram &P : Job.Programs)
      R.Programs[P.Role] = buildJobProgram(Cl, R.L, P, Options, R.FallbackSlots);
  } catch (const cl::Error &E) {
    R.Error = std::string("OpenCL call ") + E.what() + " failed: " + clErrorName(E.err());
  } catch (const std::exception &E) {
    R.Error = E.what();
  }
  R.ReadySeconds = steadySeconds() - Epoch;
  return R;
}

BackgroundBuild::BackgroundBuild(std::function<TierBuildResult()> Job, size_t EventIndex,
                                 int Nice, std::function<void()> OnDone)
    : EventIndex(EventIndex) {
  std::packaged_task<TierBuildResult()> Task(std::move(Job));
  Result = Task.get_future().share();
  Thread = std::thread([Task = std::move(Task), Nice, OnDone = std::move(OnDone)]() mutable {
    lowerThisThreadsPriority(Nice);
    Task();
    if (OnDone)
      OnDone();
  });
}

BackgroundBuild::~BackgroundBuild() {
  if (Thread.joinable())
    Thread.join();
}

bool BackgroundBuild::ready() const {
  return Result.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

} // namespace texrender
