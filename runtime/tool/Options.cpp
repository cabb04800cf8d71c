// texrender's command line: the option table, its parsing and checks, the usage text.

#include "Options.h"

#include "texcc/Support/AtomicWrite.h"
#include "texcc/Support/Numbers.h"
#include "texcc/Support/Text.h"
#include "texcc/Version.h"
#include "texrender/Error.h"
#include "texrender/Scene.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace texrender {

namespace {

const char *Usage =
    "usage: texrender scene.json -o image.png|image.exr [options]\n"
    "  --textures DIR       texcc output folder (default: scene.json \"textures\")\n"
    "  --spp N              samples per pixel\n"
    "  --size WxH           image size\n"
    "  --max-depth N        path length, Mitsuba's max_depth (1 = emitters, 2 = direct, -1 = unlimited)\n"
    "  --ao-samples N       AO rays per hit      --ao-distance D   AO ray length\n"
    "  --ao-method=parallel|loop  parallel (default): one work-item per AO ray, all rays of\n"
    "                       all hits in one launch; loop: one work-item per hit (to compare)\n"
    "  --trace=opencl|embree|auto  the trace backend (closest hit, shadow, AO rays); auto\n"
    "                       (default): embree on a CPU device, opencl otherwise\n"
    "  --seed N             random seed\n"
    "  --region X,Y,W,H     render only this W x H part of the film (--size), from pixel\n"
    "                       (X, Y), row 0 at the top; the image written is W x H and equals\n"
    "                       that part of a whole render bit for bit (scripts/farm.py tiles)\n"
    "  --frame N            readSetting(\"Frame\") = N and readSetting(\"Time\") = N / fps\n"
    "  --fps F              frames per second of --frame's Time (default 24)\n"
    "  --set NODE.ARG=VALUE live edit before rendering (repeatable)\n"
    "  --edit-script FILE   render, then per line apply an edit (set NODE.ARG=VALUE |\n"
    "                       rewire NODE.ARG=SOURCE | wait) and render again; frame k is also\n"
    "                       written as OUT.frameK.EXT; every edit is checked against the\n"
    "                       graph first (FILE:LINE:COL: error: ...)\n"
    "  --interactive        render, then read edits from standard input (same lines as an\n"
    "                       edit script; 'quit' or end of input stops): each is applied,\n"
    "                       the frame re-rendered into OUT, its edit-to-frame latency printed;\n"
    "                       a line longer than 64 KiB ends the session (exit 1)\n"
    "  --tier=auto|interp|shape  shape-mode textures: auto renders with the interp fallback\n"
    "                       while the shape kernel builds in the background; interp: the\n"
    "                       fallback only; shape: wait for the shape kernel's build\n"
    "                       (default: auto with --edit-script or --interactive, else shape)\n"
    "  --device N           OpenCL device (default 0; --list-devices lists them)\n"
    "  --threads N          threads that render (1..1024; default: every core this process\n"
    "                       may run on): the CPU device's pool and the trace backend's\n"
    "                       (Embree), which take turns within a frame\n"
    "  --lanes on|off       on (default): with two or more threads a frame renders as one\n"
    "                       lane per thread, each on its own core with every N-th row of the\n"
    "                       film, where it can (docs/cli.md, Lanes); off: one renderer whose\n"
    "                       stages run on every core\n"
    "  --view-transform Standard|AgX|Filmic  a .png's view transform, as Blender's Color\n"
    "                       Management (default: the scene's film.view, else Standard)\n"
    "  --look NAME          the view's look (\"AgX - Punchy\", \"High Contrast\", ...; None)\n"
    "  --exposure STOPS     scale by 2^STOPS before the view (default 0)\n"
    "  --gamma G            raise the display values to 1/G (default 1)\n"
    "  --ocio-config FILE   Blender's config.ocio, whose folder has the LUT files AgX and\n"
    "                       Filmic read (default: $OCIO)\n"
    "  --from-exr FILE.exr  no scene and no render: FILE's linear pixels become -o's .png\n"
    "                       through the view options above\n"
    "  --stats FILE         write stats.json\n"
    "  --check-nan          stop with an error at the first NaN or infinite texture output,\n"
    "                       naming the material, the node and the pixel\n"
    "  --variance FILE.exr  write the per-pixel variance of the image (for statistical tests)\n"
    "  --kernels DIR        fixed kernels folder (default: next to the executable)\n"
    "  --cache-dir DIR      program-binary cache (default $XDG_CACHE_HOME/texcc); --no-cache\n"
    "  --time-limit S       stop rendering after S seconds (from the start) and write the\n"
    "                       image of the passes done; a kernel build or a single device pass\n"
    "                       that runs past it is an error (exit 1, no output written)\n"
    "  --watch              render progressively into -o (rewritten at most 4 times a\n"
    "                       second) until Ctrl-C, watching scene.json, the graph and its\n"
    "                       sources: a saved change is applied (values: an upload; other\n"
    "                       graph or source changes: texcc in the background; the scene: a\n"
    "                       reload) and accumulation restarts (docs/live.md)\n"
    "  --control            with --watch: edit commands on standard input ('ID set\n"
    "                       NODE.ARG=VALUE', 'ID rewire NODE.ARG=SOURCE', 'quit'; a line\n"
    "                       longer than 64 KiB ends the session, exit 1), one JSON event a\n"
    "                       line on standard output (ready, applied, error, frame, reload)\n"
    "  --first-pass=reduced|full  with --watch: the first image after a change has one\n"
    "                       sample per pixel at 1/2, 1/4, 1/8 or 1/16 of the width and\n"
    "                       height, the finest whose predicted time fits the budget\n"
    "                       (reduced, the default), or is at full resolution (full)\n"
    "  --first-pass-budget MS  the reduced first pass's time budget (default 60 ms)\n"
    "  --serve[=PORT]       the browser preview (default port 8642; 0: any free one): runs\n"
    "                       scripts/serve.sh with the scene and the other options\n"
    "  --listen ADDR        with --serve: the address to listen on (default 127.0.0.1)\n"
    "  --quiet              no progress bar\n"
    "  --progress           the progress bar (elapsed time, ETA) and the end's summary line\n"
    "                       even when stderr is not a terminal (then one line per update)\n"
    "SIGINT (Ctrl-C) or SIGTERM stops rendering at the next pass boundary: the image (and\n"
    "--stats) of the samples done is written whole, then exit 128 + the signal (130, 143);\n"
    "a second signal ends texrender at once.\n";

/// An option's value as quoted in a message: at most 60 characters of it (an option can be a
/// whole file's worth of text: texcc::boundedExcerpt).
std::string quoted(const std::string &V) { return "'" + texcc::boundedExcerpt(V, 60) + "'"; }

int toInt(const std::string &Opt, const std::string &V) {
  try {
    size_t Pos = 0;
    long long N = std::stoll(V, &Pos);
    if (Pos == V.size() && !V.empty() && !std::isspace((unsigned char)V[0])) {
      if (N < INT_MIN || N > INT_MAX)
        throw Error(Opt + ": " + quoted(V) + " is outside the 32-bit int range");
      return int(N);
    }
  } catch (const Error &) {
    throw;
  } catch (const std::out_of_range &) {
    throw Error(Opt + ": " + quoted(V) + " is outside the 32-bit int range");
  } catch (...) {
  }
  throw Error(Opt + ": expected an integer, got " + quoted(V));
}

/// A finite number that fits a float (FLT_MAX as printed does): 1e39, inf and nan are refused
/// with the option named (std::stof took inf and nan, and 1e39 was "expected a number").
float toFloat(const std::string &Opt, const std::string &V) {
  if (V.empty() || std::isspace((unsigned char)V[0]))
    throw Error(Opt + ": expected a number, got " + quoted(V));
  errno = 0;
  char *End = nullptr;
  const double D = std::strtod(V.c_str(), &End);
  if (End == V.c_str() || *End)
    throw Error(Opt + ": expected a number, got " + quoted(V));
  if (std::isnan(D) || (std::isinf(D) && errno != ERANGE))
    throw Error(Opt + ": expected a finite number, got " + quoted(V));
  if (!texcc::fitsInFloat(D))
    throw Error(Opt + ": " + quoted(V) + " is out of range for a float (at most 3.4028235e38)");
  return float(D);
}

/// --region X,Y,W,H: four integers, X and Y at least 0, W and H at least 1 (the film's size is
/// checked once the scene is read).
std::array<int, 4> parseRegion(const std::string &S) {
  std::vector<std::string> Parts;
  std::istringstream In(S);
  for (std::string Part; std::getline(In, Part, ',');)
    Parts.push_back(Part);
  if (Parts.size() != 4 || S.back() == ',')
    throw Error("--region: expected X,Y,W,H, got '" + S + "'");
  std::array<int, 4> R{};
  for (int K = 0; K < 4; ++K)
    R[K] = toInt("--region", Parts[K]);
  if (R[0] < 0 || R[1] < 0 || R[2] < 1 || R[3] < 1)
    throw Error("--region " + S + ": X and Y must be at least 0, W and H at least 1");
  return R;
}

/// Every output's folder is checked before the render: a run that fails at its end must not
/// leave some of its outputs written and others not.
void checkOutputPath(const std::string &Path) {
  if (Path.empty())
    return;
  fs::path Dir = fs::path(Path).parent_path();
  if (!Dir.empty() && !fs::is_directory(Dir))
    throw Error(Path + ": cannot write: '" + Dir.string() + "' is not a folder");
  std::string Why;
  if (!texcc::checkReplaceable(Path, Why)) // a folder, a device (/dev/full), a FIFO
    throw Error(Path + ": cannot write: " + Why);
}

} // namespace

Options parseArgs(int Argc, char **Argv) {
  Options O;
  for (int I = 1; I < Argc; ++I) {
    const int First = I;
    std::string A = Argv[I], Value;
    bool HasInline = false;
    if (A.rfind("--", 0) == 0 && A.find('=') != std::string::npos && A.rfind("--set=", 0) != 0) {
      Value = A.substr(A.find('=') + 1);
      A = A.substr(0, A.find('='));
      HasInline = true;
    } else if (A.rfind("--set=", 0) == 0) {
      Value = A.substr(6);
      A = "--set";
      HasInline = true;
    }
    auto Next = [&]() -> std::string {
      if (HasInline)
        return Value;
      if (I + 1 >= Argc)
        throw Error(A + ": missing value");
      return Argv[++I];
    };
    if (A == "-h" || A == "--help") {
      std::cout << Usage;
      std::exit(0);
    } else if (A == "--version") {
      std::cout << "texrender " << texcc::versionString() << "\n";
      std::exit(0);
    } else if (A == "-o" || A == "--output") {
      O.Output = Next();
    } else if (A == "--textures") {
      O.Textures = Next();
    } else if (A == "--spp") {
      O.Spp = toInt(A, Next());
      if (*O.Spp < 1)
        throw Error("--spp: expected at least 1");
    } else if (A == "--size") {
      std::string S = Next();
      size_t X = S.find('x');
      if (X == std::string::npos)
        throw Error("--size: expected WxH, got '" + S + "'");
      O.Width = toInt(A, S.substr(0, X));
      O.Height = toInt(A, S.substr(X + 1));
      if (*O.Width < 1 || *O.Height < 1)
        throw Error("--size: width and height must be at least 1");
      if (std::string Why = tooManyPixels(*O.Width, *O.Height); !Why.empty())
        throw Error("--size " + S + ": " + Why);
    } else if (A == "--max-depth") {
      O.MaxDepth = toInt(A, Next());
    } else if (A == "--ao-samples") {
      O.AoSamples = toInt(A, Next());
      if (*O.AoSamples < 1)
        throw Error("--ao-samples: expected at least 1");
    } else if (A == "--ao-distance") {
      O.AoDistance = toFloat(A, Next());
    } else if (A == "--seed") {
      O.Seed = toInt(A, Next());
    } else if (A == "--region") {
      O.Region = parseRegion(Next());
    } else if (A == "--frame") {
      O.Frame = toInt(A, Next());
    } else if (A == "--fps") {
      O.Fps = toFloat(A, Next());
      if (!(O.Fps > 0))
        throw Error("--fps: expected a positive number");
    } else if (A == "--set") {
      O.Sets.push_back(Next());
    } else if (A == "--edit-script") {
      O.EditScript = Next();
    } else if (A == "--tier") {
      O.Tier = parseTierPolicy(Next());
    } else if (A == "--device") {
      O.Device = toInt(A, Next());
    } else if (A == "--threads") {
      const std::string S = Next();
      try {
        O.Threads = toInt(A, S);
      } catch (const Error &) {
        O.Threads = 0; // out of int range: the same message as any number outside 1..1024
      }
      if (*O.Threads < 1 || *O.Threads > MaxThreads)
        throw Error("--threads: expected an integer from 1 to " + std::to_string(MaxThreads) +
                    ", got " + quoted(S));
    } else if (A == "--list-devices") {
      O.ListDevices = true;
    } else if (A == "--trace") {
      O.Trace = parseTraceKind(Next());
    } else if (A == "--lanes") {
      const std::string M = Next();
      if (M != "on" && M != "off")
        throw Error("--lanes: expected on or off, got " + quoted(M));
      O.Lanes = M == "on";
    } else if (A == "--ao-method") {
      std::string M = Next();
      if (M != "parallel" && M != "loop")
        throw Error("--ao-method: expected parallel or loop, got '" + M + "'");
      O.AoLoop = M == "loop";
    } else if (A == "--watch") {
      O.Watch = true;
    } else if (A == "--control") {
      O.Control = true;
    } else if (A == "--first-pass") {
      std::string M = Next();
      if (M != "reduced" && M != "full")
        throw Error("--first-pass: expected reduced or full, got '" + M + "'");
      O.ReducedFirstPass = M == "reduced";
    } else if (A == "--first-pass-budget") {
      std::string S = Next();
      O.FirstPassBudgetMs = toFloat(A, S);
      if (!(O.FirstPassBudgetMs > 0) || !std::isfinite(O.FirstPassBudgetMs))
        throw Error("--first-pass-budget: expected a positive number of milliseconds, got '" + S + "'");
    } else if (A == "--serve") {
      O.Serve = true;
      // --serve=PORT, or --serve PORT when the next argument is a number.
      if (HasInline || (I + 1 < Argc && *Argv[I + 1] &&
                        std::string(Argv[I + 1]).find_first_not_of("0123456789") == std::string::npos))
        O.ServePort = toInt(A, Next());
      if (O.ServePort < 0 || O.ServePort > 65535)
        throw Error("--serve: expected a port from 0 (any free port) to 65535, got " +
                    std::to_string(O.ServePort));
      continue;
    } else if (A == "--listen") {
      O.Listen = Next();
      O.ListenGiven = true;
      if (O.Listen.empty())
        throw Error("--listen: expected an address");
      continue;
    } else if (A == "--interactive") {
      O.Interactive = true;
    } else if (A == "--check-nan") {
      O.CheckNan = true;
    } else if (A == "--view-transform") {
      O.ViewTransform = Next();
    } else if (A == "--look") {
      O.Look = Next();
    } else if (A == "--exposure") {
      O.Exposure = toFloat(A, Next());
    } else if (A == "--gamma") {
      O.Gamma = toFloat(A, Next());
    } else if (A == "--ocio-config") {
      O.OcioConfig = Next();
      if (O.OcioConfig.empty())
        throw Error("--ocio-config: expected a file");
    } else if (A == "--from-exr") {
      O.FromExr = Next();
    } else if (A == "--stats") {
      O.Stats = Next();
    } else if (A == "--variance") {
      O.Variance = Next();
      if (fs::path(O.Variance).extension() != ".exr")
        throw Error("--variance " + O.Variance + ": expected an .exr file");
    } else if (A == "--kernels") {
      O.KernelDir = Next();
    } else if (A == "--cache-dir") {
      O.CacheDir = Next();
    } else if (A == "--no-cache") {
      O.CacheDir.clear();
    } else if (A == "--time-limit") {
      std::string S = Next();
      O.TimeLimit = toFloat(A, S);
      if (!(O.TimeLimit > 0) || !std::isfinite(O.TimeLimit))
        throw Error("--time-limit: expected a positive number of seconds, got '" + S + "'");
    } else if (A == "--progress") {
      O.ForceProgress = true;
    } else if (A == "--quiet" || A == "-q") {
      O.Quiet = true;
    } else if (A.size() > 1 && A[0] == '-') {
      throw Error("unknown option '" + A + "' (see --help)");
    } else if (O.Scene.empty()) {
      O.Scene = A;
    } else {
      throw Error("unexpected argument '" + A + "' (one scene file only)");
    }
    for (int K = First; K <= I; ++K)
      O.Forward.push_back(Argv[K]);
  }
  if (O.ListDevices)
    return O;
  // readSetting("Time") is a float: a frame time past its range was Inf (a black texture).
  if (const double Time = double(O.Frame) / O.Fps; !texcc::fitsInFloat(Time)) {
    std::ostringstream M;
    M << "--frame " << O.Frame << " --fps " << O.Fps << ": the frame's time, " << Time
      << " s, is out of range for a float (readSetting(\"Time\"); at most 3.4028235e38)";
    throw Error(M.str());
  }
  if (!O.FromExr.empty()) {
    std::string Ext = fs::path(O.Output).extension().string();
    if (!O.Scene.empty() || O.Serve || O.Watch || (Ext != ".png" && Ext != ".PNG"))
      throw Error("--from-exr " + O.FromExr + ": converts an image: no scene, and -o a .png");
  } else if (O.Scene.empty()) {
    throw Error("no scene file given (usage: texrender scene.json -o image.png)");
  }
  if (O.Serve) {
    if (!O.Output.empty() || O.Watch || O.Control || O.Interactive || !O.EditScript.empty() ||
        O.TimeLimit > 0 || !O.Variance.empty() || !O.Sets.empty() || !O.Stats.empty())
      throw Error("--serve runs the preview server, which renders with --watch --control into "
                  "a folder of its own: it cannot be combined with -o, --watch, --control, "
                  "--interactive, --edit-script, --time-limit, --variance, --set or --stats");
    return O;
  }
  if (O.ListenGiven)
    throw Error("--listen: only with --serve");
  if (O.Control && !O.Watch)
    throw Error("--control: only with --watch (it drives a watch session)");
  if (O.Output.empty())
    throw Error("no output image given (-o image.png or -o image.exr)");
  std::string Ext = fs::path(O.Output).extension().string();
  if (Ext != ".png" && Ext != ".exr" && Ext != ".PNG" && Ext != ".EXR")
    throw Error("-o " + O.Output + ": unknown image format (expected .png or .exr)");
  if (O.Watch && (!O.EditScript.empty() || O.Interactive || O.TimeLimit > 0 ||
                  !O.Variance.empty() || !O.Sets.empty()))
    throw Error("--watch renders until Ctrl-C: it cannot be combined with --edit-script, "
                "--interactive, --time-limit, --variance or --set (edit graph.json instead)");
  if (O.TimeLimit > 0 && (!O.EditScript.empty() || O.Interactive))
    throw Error("--time-limit limits one render: it cannot be combined with --edit-script or "
                "--interactive");
  const bool Png = Ext == ".png" || Ext == ".PNG";
  if (!Png && (O.ViewTransform || O.Look || O.Exposure || O.Gamma))
    throw Error("--view-transform, --look, --exposure and --gamma make the picture of a .png: "
                "-o " + O.Output + " is linear (as Blender's EXR)");
  if (O.OcioConfig.empty())
    if (const char *Env = std::getenv("OCIO"))
      O.OcioConfig = Env;
  for (const std::string *Out : {&O.Output, &O.Stats, &O.Variance})
    checkOutputPath(*Out);
  return O;
}

} // namespace texrender
