// texrender: renders a scene with texcc's texture kernel (docs/runtime.md).
//   texrender scene.json [--textures OUTDIR] [--spp N] [--size WxH] [--max-depth N]
//             [--set NODE.ARG=VALUE]... [--edit-script FILE] [--device N]
//             -o image.png|image.exr [--stats stats.json]
// Exit 0 on success, 1 on any error, with a one-line reason first.
// The command line is parsed in Options.cpp; this file runs what it asks for: one render, an
// edit script, --interactive, --watch (--control) or --serve.
#include "Options.h"

#include "texcc/OutOfMemory.h"
#include "texcc/StackGuard.h"
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texrender/LiveEdit.h"
#include "texrender/Renderer.h"
#include "texrender/SlowStep.h"
#include "texrender/Stats.h"
#include "texrender/Lanes.h"
#include "texrender/Threads.h"
#include "texrender/ViewTransform.h"
#include "texrender/Watch.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <optional>
#include <signal.h>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

/// An edit script's error, printed as a compiler's: "edits.txt:LINE:COL: error: MESSAGE".
struct ScriptError {
  std::string Text;
};

/// An edit script: its edits and the line each came from.
struct EditScript {
  std::string Path;
  std::vector<Edit> Edits;
  std::vector<unsigned> Lines;
};

ScriptError scriptError(const std::string &Path, unsigned Line, unsigned Col,
                        const std::string &Message) {
  return {Path + ":" + std::to_string(Line) + ":" + std::to_string(Col) + ": error: " + Message};
}

/// Reads and parses an edit script (a regular file: a FIFO, a device or a folder is refused).
EditScript readEditScript(const std::string &Path) {
  EditScript S{Path, {}, {}};
  std::istringstream In(readWholeFile(Path, " edit script"));
  std::string Line;
  for (unsigned N = 1; std::getline(In, Line); ++N) {
    size_t B = Line.find_first_not_of(" \t\r");
    if (B == std::string::npos || Line[B] == '#')
      continue;
    if (Line.find('\0') != std::string::npos)
      throw scriptError(Path, N, unsigned(Line.find('\0') + 1), "a NUL byte (not a text file)");
    try {
      S.Edits.push_back(parseEdit(Line));
      S.Lines.push_back(N);
    } catch (const Error &E) {
      throw scriptError(Path, N, unsigned(B + 1), E.what());
    }
  }
  return S;
}

/// The --set edits and the script's, checked (validated once, LiveEditor::check) in the order
/// they are applied, before anything is rendered; applied later without being validated again.
struct CheckedEdits {
  std::vector<CheckedEdit> Sets, Script;
};

/// Checks Sets and then the script's edits (moved out of Script) against the graph. A refused
/// one is an error: "edit 'TEXT': why" for a --set, "FILE:LINE:COL: error: why" for a line.
CheckedEdits checkEdits(const LiveEditor &Editor, std::vector<Edit> Sets, EditScript &Script) {
  const size_t NumSets = Sets.size();
  std::vector<std::string> SetTexts;
  for (const Edit &E : Sets)
    SetTexts.push_back(E.Text);
  std::vector<Edit> All = std::move(Sets);
  std::move(Script.Edits.begin(), Script.Edits.end(), std::back_inserter(All));
  Script.Edits.clear();
  std::vector<CheckedEdit> Checked;
  if (std::optional<EditProblem> P = Editor.check(std::move(All), Checked)) {
    if (P->Index < NumSets)
      throw Error("edit '" + SetTexts[P->Index] + "': " + P->Message);
    throw scriptError(Script.Path, Script.Lines[P->Index - NumSets], P->Col, P->Message);
  }
  CheckedEdits Out;
  Out.Script.assign(std::make_move_iterator(Checked.begin() + NumSets),
                    std::make_move_iterator(Checked.end()));
  Checked.erase(Checked.begin() + NumSets, Checked.end());
  Out.Sets = std::move(Checked);
  return Out;
}

/// --time-limit: a thread that ends the process when a step that cannot be interrupted runs past
/// the limit: loading and building before the deadline, a single device pass for longer than the
/// limit. Rendering itself stops at a pass boundary (RendererOptions::Deadline). The watchdog is
/// idle while outputs are written (phase ""), so that it never leaves a temporary file behind.
class Watchdog {
public:
  Watchdog(double Limit, double Deadline) : Limit(Limit), Deadline(Deadline) {
    Thread = std::thread([this] { watch(); });
  }
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> Lock(M);
      Done = true;
    }
    Wake.notify_all();
    Thread.join();
  }
  /// What the run does now, for the error ("building the kernels"); "" pauses the watchdog.
  void phase(const char *What) { Phase.store(What); }
  /// Renderer::OnPass: times the pass in flight.
  void pass(bool InPass) { PassStart.store(InPass ? steadySeconds() : 0.0); }

private:
  void watch() {
    std::unique_lock<std::mutex> Lock(M);
    while (!Wake.wait_for(Lock, std::chrono::milliseconds(20), [this] { return Done; })) {
      const char *What = Phase.load();
      double Now = steadySeconds(), Start = PassStart.load();
      if (Start > 0 && Now > Start + Limit)
        fire("rendering (a single device pass ran longer than the limit)");
      else if (Start == 0 && *What && Now > Deadline)
        fire(What);
    }
  }
  [[noreturn]] void fire(const char *What) {
    std::fprintf(stderr, "texrender: error: --time-limit %g s: exceeded while %s\n", Limit, What);
    std::fflush(stderr);
    // The device call cannot be interrupted. Nothing is half-written: outputs are renamed into
    // place, and the watchdog is idle while they are written.
    _exit(1);
  }

  double Limit, Deadline;
  std::atomic<const char *> Phase{""};
  std::atomic<double> PassStart{0.0};
  std::mutex M;
  std::condition_variable Wake;
  bool Done = false;
  std::thread Thread;
};

/// Sets the watchdog's phase, if there is a watchdog.
void phase(Watchdog *W, const char *What) {
  if (W)
    W->phase(What);
}

/// The signal (SIGINT, SIGTERM) that asked the run to stop; 0: none. The handler only stores
/// it: rendering stops at the next pass boundary (RendererOptions::AfterPass) and the outputs
/// are written by the main thread as usual.
std::atomic<int> StopSignal{0};

extern "C" void onStopSignal(int Sig) { StopSignal.store(Sig); }

/// SA_RESETHAND: a second Ctrl-C ends the process at once (a kernel build or a device pass
/// cannot be interrupted). No SA_RESTART, so that --interactive's read of stdin returns.
void installStopHandlers() {
  struct sigaction Act {};
  Act.sa_handler = onStopSignal;
  sigemptyset(&Act.sa_mask);
  Act.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &Act, nullptr);
  sigaction(SIGTERM, &Act, nullptr);
}

const char *signalName(int Sig) { return Sig == SIGINT ? "SIGINT" : Sig == SIGTERM ? "SIGTERM" : "a signal"; }

/// "1m05s", "3.2 s": the progress bar's times.
std::string shortDuration(double S) {
  char Buf[32];
  if (S < 60)
    std::snprintf(Buf, sizeof Buf, "%.1fs", S);
  else if (S < 3600)
    std::snprintf(Buf, sizeof Buf, "%dm%02ds", int(S) / 60, int(S) % 60);
  else
    std::snprintf(Buf, sizeof Buf, "%dh%02dm", int(S) / 3600, int(S) / 60 % 60);
  return Buf;
}

/// The progress bar of a render (after its first second): samples done, elapsed time and the
/// ETA from the rate so far. On a terminal it redraws one line (at most 10 times a second);
/// elsewhere (--progress) it prints one line per update, at most once a second.
class ProgressBar {
public:
  explicit ProgressBar(bool Tty) : Tty(Tty) {}
  void update(const PassProgress &P) {
    if (P.Seconds < 1.0 || P.Seconds - Last < (Tty ? 0.1 : 1.0))
      return;
    Last = P.Seconds;
    const int Width = 30, Fill = int(Width * double(P.SamplesDone) / P.Spp);
    double Eta = P.Seconds / P.SamplesDone * (P.Spp - P.SamplesDone);
    std::fprintf(stderr, "%stexrender: [%s%s] %3d%% %d/%d spp, %s elapsed, ETA %s%s", Tty ? "\r" : "",
                 std::string(Fill, '#').c_str(), std::string(Width - Fill, ' ').c_str(),
                 int(100.0 * P.SamplesDone / P.Spp), P.SamplesDone, P.Spp,
                 shortDuration(P.Seconds).c_str(), shortDuration(Eta).c_str(), Tty ? "  " : "\n");
    std::fflush(stderr);
    Drew = Tty;
  }
  /// Ends the redrawn line, if any (before anything else is printed).
  void finish() {
    if (Drew)
      std::fprintf(stderr, "\n");
    Drew = false;
    Last = 0;
  }

private:
  bool Tty, Drew = false;
  double Last = 0;
};

/// The line after a render with a progress bar: "texrender: 64 spp at 512x512 in 3.21 s,
/// 1.24 M rays/s (primary, bounce, shadow and AO rays)".
void printSummary(const FrameStats &F, int W, int H) {
  double Rays = double(F.PrimaryRays + F.BounceRays + F.ShadowRays + F.AoRays);
  std::fprintf(stderr, "texrender: %d spp at %dx%d in %.2f s, %.2f M rays/s (primary, bounce, "
                       "shadow and AO rays)\n",
               F.SamplesDone, W, H, F.Seconds, F.Seconds > 0 ? Rays / F.Seconds / 1e6 : 0.0);
}

std::string frameName(const std::string &Out, size_t K) {
  fs::path P(Out);
  return (P.parent_path() / (P.stem().string() + ".frame" + std::to_string(K) + P.extension().string()))
      .string();
}

double now() { return steadySeconds(); }

/// The builds between one frame and the next: those the frame waited for (foreground) and
/// those the background thread finished meanwhile.
class BuildCounter {
public:
  explicit BuildCounter(Renderer &R) : R(R) {}
  void record(FrameRecord &F) {
    F.KernelBuilds = R.cl().foregroundBuilds() - Foreground;
    F.BackgroundBuilds = R.cl().backgroundBuilds() - Background;
    F.BuildWaitSeconds = R.tiers().foregroundBuildSeconds() - WaitSeconds;
    Foreground = R.cl().foregroundBuilds();
    Background = R.cl().backgroundBuilds();
    WaitSeconds = R.tiers().foregroundBuildSeconds();
  }

private:
  Renderer &R;
  unsigned Foreground = 0, Background = 0;
  double WaitSeconds = 0;
};

/// The step an out-of-memory error names while the edit Text is applied: "applying the edit
/// 'a.b=1'" (a long edit, such as a large array value, cut after 60 characters).
std::string editStep(const std::string &Text) {
  return "applying the edit '" + (Text.size() > 60 ? Text.substr(0, 60) + "..." : Text) + "'";
}

/// Editor.apply(E, R) as the step editStep (LiveEditor's own steps, such as "encoding the
/// graph for a live edit", are named inside it). E: an Edit or a CheckedEdit; Text: its line's
/// text, read before E is moved into the editor (no copy outside a step).
template <typename EditT>
EditResult applyEdit(EditT &&E, const std::string &Text, LiveEditor &Editor, Renderer &R) {
  const std::string Step = editStep(Text);
  return texcc::whileAllocating(Step.c_str(),
                                [&] { return Editor.apply(std::forward<EditT>(E), R); });
}

/// Applies E (an Edit or a CheckedEdit, whose line's text is Text, read before E is moved) to
/// the renderer and renders the next frame (Image), counting its builds.
template <typename EditT>
FrameRecord renderAfterEdit(EditT &&E, const std::string &Text, LiveEditor &Editor, Renderer &R,
                            BuildCounter &Builds, std::vector<float> &Image) {
  const std::string Step = editStep(Text);
  return texcc::whileAllocating(Step.c_str(), [&] {
    FrameRecord F;
    F.EditText = Text;
    EditResult Res = Editor.apply(std::forward<EditT>(E), R);
    F.EditSeconds = Res.Seconds;
    F.IdleSeconds = Res.IdleSeconds;
    F.Rebuilt = Res.Rebuilt;
    F.BackgroundRebuild = Res.Background;
    Image = texcc::whileAllocating("rendering", [&] { return R.render(F.Frame); });
    Builds.record(F);
    return F;
  });
}

/// One line on standard output per interactive frame: what the edit cost until the frame was
/// there, split, and whether it built a kernel.
void printLatency(size_t K, const FrameRecord &F) {
  std::printf("frame %zu: '%s': edit %.4f s + frame %.4f s = %.4f s to frame; %u kernel "
              "build(s) waited for%s%s\n",
              K, F.EditText.c_str(), F.EditSeconds, F.Frame.Seconds, F.EditSeconds + F.Frame.Seconds,
              F.KernelBuilds, F.Frame.Tier.empty() ? "" : "; tier ", F.Frame.Tier.c_str());
  std::fflush(stdout);
}

/// --interactive: edits from standard input until 'quit' or its end. A bad edit is reported
/// and skipped (the session goes on); the image OUT is rewritten after every frame. A line
/// longer than MaxEditLine ends the session like the end of input, with an error: the
/// return value (false).
bool interactiveSession(const Options &O, const Scene &S, const ViewTransform *View,
                        LiveEditor &Editor, Renderer &R,
                        BuildCounter &Builds, std::vector<float> &Image,
                        std::vector<FrameRecord> &Frames) {
  const bool Tty = isatty(0);
  std::string Line;
  for (unsigned N = 1;; ++N) {
    if (Tty)
      std::fprintf(stderr, "edit> ");
    LineRead Got = readBoundedLine(std::cin, Line, MaxEditLine);
    if (Got == LineRead::End || StopSignal.load())
      break;
    if (Got == LineRead::TooLong) {
      std::fprintf(stderr, "texrender: error: standard input:%u: line longer than %zu bytes; the "
                           "interactive session ends\n", N, MaxEditLine);
      return false;
    }
    size_t B = Line.find_first_not_of(" \t\r");
    if (B == std::string::npos || Line[B] == '#')
      continue;
    if (Line.compare(B, 4, "quit") == 0)
      break;
    try {
      Edit E = parseEdit(Line);
      Frames.push_back(renderAfterEdit(E, E.Text, Editor, R, Builds, Image));
    } catch (const Error &E) {
      std::fprintf(stderr, "texrender: error: %s\n", E.what());
      continue;
    }
    printLatency(Frames.size() - 1, Frames.back());
    const RenderSettings &G = S.Render;
    writeImage(O.Output, G.RegionWidth ? G.RegionWidth : G.Width,
               G.RegionWidth ? G.RegionHeight : G.Height, Image, View);
  }
  return true;
}

/// --serve: texrender itself serves nothing; it becomes the preview server, scripts/serve.sh
/// of texcc's source tree ($TEXRENDER_SERVE_SCRIPT overrides it), which runs this texrender
/// with --watch --control (docs/live.md, "Browser preview").
[[noreturn]] void execServe(const Options &O, const char *Argv0) {
  const char *Override = std::getenv("TEXRENDER_SERVE_SCRIPT");
  std::string Script = Override && *Override ? Override : TEXCC_SOURCE_DIR "/scripts/serve.sh";
  if (::access(Script.c_str(), X_OK) != 0)
    throw Error("--serve: the preview server's script '" + Script + "' is " +
                (::access(Script.c_str(), F_OK) == 0 ? "not executable" : "missing") +
                " (it comes with texcc's source tree: scripts/serve.sh)");
  std::error_code EC;
  fs::path Self = fs::read_symlink("/proc/self/exe", EC);
  if (EC)
    Self = fs::absolute(Argv0);
  std::vector<std::string> Args{Script, "--port", std::to_string(O.ServePort), "--listen",
                                O.Listen, "--texrender", Self.string(), "--"};
  Args.insert(Args.end(), O.Forward.begin(), O.Forward.end());
  std::vector<char *> Ptrs;
  for (std::string &A : Args)
    Ptrs.push_back(A.data());
  Ptrs.push_back(nullptr);
  std::fflush(nullptr);
  ::execv(Script.c_str(), Ptrs.data());
  throw Error("--serve: cannot run '" + Script + "': " + std::strerror(errno));
}

/// scene.json with the command line's overrides (--spp, --size, --region, --frame, ...).
Scene loadSceneWithOptions(const Options &O) {
  Scene S = loadScene(O.Scene);
  if (O.Spp) S.Render.Spp = *O.Spp;
  if (O.Width) S.Render.Width = *O.Width, S.Render.Height = *O.Height;
  if (O.MaxDepth) S.Render.MaxDepth = *O.MaxDepth;
  if (O.AoSamples) S.Render.AoSamples = *O.AoSamples;
  if (O.AoDistance) S.Render.AoDistance = *O.AoDistance;
  if (O.Seed) S.Render.Seed = unsigned(*O.Seed);
  S.Render.Frame = O.Frame;
  S.Render.Time = float(double(O.Frame) / O.Fps);
  if (O.Region) {
    const std::array<int, 4> &G = *O.Region;
    if (int64_t(G[0]) + G[2] > S.Render.Width || int64_t(G[1]) + G[3] > S.Render.Height)
      throw Error("--region " + std::to_string(G[0]) + "," + std::to_string(G[1]) + "," +
                  std::to_string(G[2]) + "," + std::to_string(G[3]) + ": outside the " +
                  std::to_string(S.Render.Width) + "x" + std::to_string(S.Render.Height) + " film");
    S.Render.RegionX = G[0], S.Render.RegionY = G[1];
    S.Render.RegionWidth = G[2], S.Render.RegionHeight = G[3];
  }
  return S;
}

/// The .png's view (Blender's Color Management): the scene's film.view (Scene's default for
/// --from-exr) with the command line's settings over it, the OCIO config from --ocio-config or
/// $OCIO. Made before the render, so that a missing LUT file is an error before any work.
/// Null for an .exr and for plain sRGB.
std::shared_ptr<ViewTransform> makeViewTransform(const Options &O, const ViewSettings &Scene) {
  std::string Ext = fs::path(O.Output).extension().string();
  if (Ext != ".png" && Ext != ".PNG")
    return nullptr;
  ViewSettings V = Scene;
  if (O.ViewTransform) V.Transform = *O.ViewTransform;
  if (O.Look) V.Look = *O.Look;
  if (O.Exposure) V.Exposure = *O.Exposure;
  if (O.Gamma) V.Gamma = *O.Gamma;
  V.Config = O.OcioConfig;
  if (V.isPlainSrgb())
    return nullptr;
  return std::make_shared<ViewTransform>(V);
}

/// stats.json: statsJson's, with the threads that rendered: "pool", the count each pool was
/// given (--threads, else every core), and "openclComputeUnits", the device's own count (on
/// PoCL's CPU device, its pool's threads) and "pinned", whether the pools' threads are pinned
/// one per CPU (Threads.h).
/// "lanes", the lanes the first frame rendered in (1: one renderer on every core), with
/// "lanesWhyNot", why not in lanes, or "laneMemoryBytes", the lanes' device memory, and
/// "laneReadySeconds" and "laneDoneSeconds", when each lane was ready and done (Lanes.h).
nlohmann::json statsWithThreads(Renderer &R, const Layout &L, const std::vector<FrameRecord> &Frames,
                                double Seconds, const LaneReport &Lanes, const std::string &WhyNot) {
  nlohmann::json J = statsJson(R, L, Frames, Seconds);
  J["threads"] = {{"pool", renderThreads()},
                  {"given", renderThreadsGiven()},
                  {"openclComputeUnits", R.cl().device().getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>()},
                  {"pinned", renderThreadsPinned()},
                  {"lanes", std::max(1u, Lanes.Lanes)}};
  if (Lanes.Lanes) {
    J["threads"]["laneMemoryBytes"] = Lanes.MemoryBytes;
    J["threads"]["laneReadySeconds"] = Lanes.ReadySeconds;
    J["threads"]["laneDoneSeconds"] = Lanes.DoneSeconds;
  }
  else
    J["threads"]["lanesWhyNot"] = WhyNot;
  return J;
}

/// Why the first frame does not render in lanes (Lanes.h; "": it does).
std::string whyNoLanes(const Options &O, bool EditSession, bool HasSets, Renderer &R,
                       const RendererOptions &RO) {
  if (!O.Lanes)
    return "--lanes off";
  if (EditSession)
    return "an edit session (the edits go to one renderer)";
  if (HasSets)
    return "--set edits (they go to one renderer)";
  if (O.TimeLimit > 0)
    return "--time-limit (the lanes would stop at different passes)";
  return lanesUnavailable(R, RO, renderThreads());
}

int run(int Argc, char **Argv) try {
  double T0 = now();
  Options O = parseArgs(Argc, Argv);
  // Before any OpenCL call and any thread: PoCL sizes its pool from the environment when the
  // platform is first queried (Threads.h).
  setRenderThreads(unsigned(O.Threads.value_or(0)));
  if (O.ListDevices) {
    auto Devs = listDevices();
    if (Devs.empty())
      throw Error("no OpenCL device found");
    for (auto &D : Devs)
      std::cout << D << "\n";
    return 0;
  }
  if (O.Serve)
    execServe(O, Argv[0]);
  if (!O.FromExr.empty()) {
    const std::shared_ptr<ViewTransform> View = makeViewTransform(O, ViewSettings());
    ImageRGBA In = loadExr(O.FromExr);
    std::vector<float> RGB(size_t(In.Width) * In.Height * 3);
    for (size_t I = 0; I < RGB.size() / 3; ++I)
      for (int C = 0; C < 3; ++C)
        RGB[3 * I + C] = In.Pixels[4 * I + C];
    writeImage(O.Output, In.Width, In.Height, RGB, View.get());
    return 0;
  }
  installStopHandlers();
  std::unique_ptr<Watchdog> Dog;
  if (O.TimeLimit > 0)
    Dog = std::make_unique<Watchdog>(O.TimeLimit, T0 + O.TimeLimit);
  // A step over a second says so (SlowStep.h) where texrender narrates: a terminal, --progress,
  // and --watch sessions (serve.py shows their lines); never with --quiet.
  setSlowStepAnnouncements(!O.Quiet && (O.ForceProgress || isatty(2) || O.Watch));
  phase(Dog.get(), "loading the scene");
  Scene S = [&] {
    SlowStep Step("loading the scene");
    return loadSceneWithOptions(O);
  }();
  const std::shared_ptr<ViewTransform> View = makeViewTransform(O, S.Render.View);
  // The size of every image written: the region's, or the film's.
  const RenderSettings &G = S.Render;
  const int OutW = G.RegionWidth ? G.RegionWidth : G.Width, OutH = G.RegionWidth ? G.RegionHeight : G.Height;
  std::string TexDir = O.Textures.empty() ? S.TexturesDir : O.Textures;
  if (TexDir.empty())
    throw Error(O.Scene + ": no texture folder: give --textures OUTDIR or \"textures\" in the scene");
  Layout L = loadLayout(TexDir);
  EditScript ScriptFile = O.EditScript.empty() ? EditScript() : readEditScript(O.EditScript);
  const bool HasScript = !ScriptFile.Edits.empty();
  std::vector<Edit> Sets;
  for (auto &Text : O.Sets)
    Sets.push_back(parseEdit(Text));

  RendererOptions RO;
  RO.Device = O.Device;
  RO.CacheDir = O.CacheDir;
  RO.KernelDir = O.KernelDir;
  const bool ShowProgress = !O.Quiet && (O.ForceProgress || isatty(2));
  ProgressBar Bar(isatty(2));
  RO.AfterPass = [&](const PassProgress &P) {
    if (ShowProgress)
      Bar.update(P);
    return StopSignal.load() == 0;
  };
  RO.CheckNan = O.CheckNan;
  RO.AoPerHitLoop = O.AoLoop;
  RO.Trace = O.Trace;
  if (Dog) {
    RO.Deadline = T0 + O.TimeLimit;
    RO.OnPass = [W = Dog.get()](bool InPass) { W->pass(InPass); };
  }
  // Tiered pays off when edits follow; a single render waits for the shape build instead
  // (docs/runtime.md, Tiers: the interp frame is slower and the background build competes).
  const bool EditSession = HasScript || O.Interactive || O.Watch;
  RO.Tier = O.Tier.value_or(EditSession ? TierPolicy::Auto : TierPolicy::Shape);
  // Likewise an interp kernel gets value-stack headroom only when edits may need it.
  RO.InterpStackHeadroom = EditSession;
  if (O.Watch) {
    // The preview's view is the one at the start: a reloaded scene's film.view does not change it.
    setPreviewViewTransform(View);
    WatchOptions W;
    W.ScenePath = O.Scene, W.Output = O.Output, W.Width = OutW, W.Height = OutH;
    W.LoadScene = [&O] { return loadSceneWithOptions(O); };
    W.Renderer = RO;
    // One sample per pixel a pass: the first refined image after an edit comes after one
    // sample, not after 2^18 paths' worth (accumulate.cl sums sample after sample, so the
    // image is the same bit for bit).
    W.Renderer.MaxPathsPerPass = size_t(OutW) * size_t(OutH);
    W.Stop = &StopSignal;
    W.Control = O.Control;
    W.ReducedFirstPass = O.ReducedFirstPass;
    W.FirstPassBudget = O.FirstPassBudgetMs / 1000;
    WatchResult Res = runWatch(std::move(W), L);
    int Sig = StopSignal.load();
    return Sig ? 128 + Sig : Res.Ok ? 0 : 1;
  }
  // Every edit is checked against the graph before the kernel build and the first frame: a
  // bad one is an error that leaves no frame written. The frames apply the checked edits.
  std::unique_ptr<LiveEditor> Editor;
  CheckedEdits Checked;
  if (!Sets.empty() || HasScript || O.Interactive) {
    texcc::whileAllocating("reading the graph for live edits",
                           [&] { Editor = std::make_unique<LiveEditor>(L); });
    texcc::whileAllocating("checking the edits",
                           [&] { Checked = checkEdits(*Editor, std::move(Sets), ScriptFile); });
  }
  std::vector<CheckedEdit> &Script = Checked.Script;
  phase(Dog.get(), "building the kernels");
  Renderer R(S, L, RO);
  if (int Sig = StopSignal.load()) {
    std::fprintf(stderr, "texrender: %s before the first pass: nothing written\n", signalName(Sig));
    return 128 + Sig;
  }
  phase(Dog.get(), "applying the --set edits");

  std::vector<FrameRecord> Frames;
  FrameRecord First;
  for (CheckedEdit &E : Checked.Sets) {
    EditResult Res = applyEdit(std::move(E), E.line().Text, *Editor, R);
    First.EditSeconds += Res.Seconds;
    First.Rebuilt |= Res.Rebuilt;
  }
  std::vector<float> Variance;
  BuildCounter Builds(R);
  // Between passes the render stops by itself at the deadline; only a pass is timed.
  phase(Dog.get(), "");
  const std::string WhyNot = whyNoLanes(O, EditSession, !Checked.Sets.empty(), R, RO);
  LaneReport Lanes;
  std::vector<float> Image = texcc::whileAllocating("rendering", [&] {
    std::vector<float> *Var = O.Variance.empty() ? nullptr : &Variance;
    if (WhyNot.empty())
      return renderInLanes(R, S, L, RO, renderThreads(), First.Frame, Var, &Lanes);
    return R.render(First.Frame, Var);
  });
  if (ShowProgress) {
    Bar.finish();
    printSummary(First.Frame, OutW, OutH);
  }
  if (First.Frame.Interrupted)
    std::fprintf(stderr, "texrender: note: %s: stopped after %d of %d samples per pixel (%u "
                         "passes); the image averages those\n",
                 signalName(StopSignal.load()), First.Frame.SamplesDone, S.Render.Spp,
                 First.Frame.Passes);
  if (First.Frame.TimeLimited)
    std::fprintf(stderr, "texrender: note: --time-limit %g s: stopped after %d of %d samples per "
                         "pixel (%u passes); the image averages those\n",
                 O.TimeLimit, First.Frame.SamplesDone, S.Render.Spp, First.Frame.Passes);
  Builds.record(First);
  Frames.push_back(First);
  if (Script.empty() && !O.Interactive) {
    // One render: its outputs appear together or not at all (Image.h, OutputGroup).
    OutputGroup Outputs;
    if (!O.Variance.empty())
      Outputs.addImage(O.Variance, OutW, OutH, Variance);
    Outputs.addImage(O.Output, OutW, OutH, Image, View.get());
    if (!O.Stats.empty())
      Outputs.addText(O.Stats, statsWithThreads(R, L, Frames, now() - T0, Lanes, WhyNot).dump(2) + "\n");
    Outputs.commit();
    if (int Sig = StopSignal.load())
      return 128 + Sig;
    return 0;
  }
  if (!O.Variance.empty())
    writeImage(O.Variance, OutW, OutH, Variance);
  if (!Script.empty())
    writeImage(frameName(O.Output, 0), OutW, OutH, Image, View.get());
  for (size_t K = 0; K < Script.size() && !StopSignal.load(); ++K) {
    Frames.push_back(
        renderAfterEdit(std::move(Script[K]), Script[K].line().Text, *Editor, R, Builds, Image));
    writeImage(frameName(O.Output, K + 1), OutW, OutH, Image, View.get());
  }
  writeImage(O.Output, OutW, OutH, Image, View.get());
  bool SessionOk = !O.Interactive || StopSignal.load() ||
                   interactiveSession(O, S, View.get(), *Editor, R, Builds, Image, Frames);
  if (!O.Stats.empty())
    writeTextFile(O.Stats, statsWithThreads(R, L, Frames, now() - T0, Lanes, WhyNot).dump(2) + "\n");
  if (int Sig = StopSignal.load())
    return 128 + Sig;
  return SessionOk ? 0 : 1;
} catch (const ScriptError &E) {
  std::fprintf(stderr, "%s\n", E.Text.c_str());
  return 1;
}

} // namespace

/// run() with every error turned into its one-line reason and exit status 1.
static int runAndReport(int Argc, char **Argv) {
  try {
    return run(Argc, Argv);
  } catch (const Error &E) {
    std::fprintf(stderr, "texrender: error: %s\n", E.what());
  } catch (const cl::Error &E) {
    std::fprintf(stderr, "texrender: error: OpenCL call %s failed: %s\n", E.what(),
                 clErrorName(E.err()).c_str());
  } catch (const std::bad_alloc &E) {
    texcc::reportOutOfMemory("texrender", E); // "out of memory while ..." (texcc/OutOfMemory.h)
  } catch (const std::exception &E) { // nlohmann's: what it quotes is bounded too
    std::fprintf(stderr, "texrender: error: %s\n", texcc::boundedMessage(E.what()).c_str());
  }
  return 1;
}

int main(int Argc, char **Argv) {
  // PoCL compiles kernels with clang in this process, recursively: a texture kernel holding a
  // huge expression needs a deep stack (docs/reliability.md).
  return texcc::runWithLargeStack([&] { return runAndReport(Argc, Argv); }, "texrender");
}
