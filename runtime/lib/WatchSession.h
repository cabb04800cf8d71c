// texrender --watch's session (runtime/lib only): the Session class, shared by Watch.cpp (the
// session: files, commands, texcc in the background) and WatchFrames.cpp (rendering and writing
// the progressive image); WatchInputs.cpp reads what the session watches. Watch.h is the API.
#ifndef TEXRENDER_LIB_WATCHSESSION_H
#define TEXRENDER_LIB_WATCHSESSION_H

#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texrender/Watch.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <functional>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <signal.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace texrender {
namespace watch {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

inline double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline void say(const std::string &Line) {
  std::fprintf(stderr, "texrender: watch: %s\n", texcc::boundedMessage(Line).c_str());
  std::fflush(stderr);
}

inline std::string ms(double Seconds) { return std::to_string(int(Seconds * 1000 + 0.5)) + " ms"; }

/// Milliseconds rounded to 0.01, for the control channel's events.
inline double eventMs(double Seconds) { return std::round(Seconds * 1e5) / 100; }

/// After a reduced first pass, full-resolution rendering starts once no change has come for
/// this long (docs/live.md).
constexpr double ReducedPause = 0.25;

/// A line of standard input, as the control channel's thread read it.
struct Command {
  std::string Text;
  double ReadAt = 0; // when its newline arrived (the edit's latency counts from there)
  unsigned LineNo = 0;
};

/// Wakes the session's idle wait before its next poll of the files: a line of standard input
/// read (ControlInput), texcc's process ended (SourceJob). Shared with the threads that
/// notify it (ControlInput's reader is detached and may outlive the session).
class Wake {
public:
  void notify() {
    {
      std::lock_guard<std::mutex> Lock(M);
      Flag = true;
    }
    Cv.notify_all();
  }
  /// Waits at most Ms milliseconds for a notify() since the last wait returned.
  void waitFor(int Ms) {
    std::unique_lock<std::mutex> Lock(M);
    Cv.wait_for(Lock, std::chrono::milliseconds(Ms), [this] { return Flag; });
    Flag = false;
  }

private:
  std::mutex M;
  std::condition_variable Cv;
  bool Flag = false;
};

/// --control's standard input. A thread reads the lines (bounded, as --interactive does) into a
/// queue, so that a command is timed when it arrives rather than when the render loop gets to
/// it, and the idle loop wakes at once (W). The thread is detached: it may stay blocked in a
/// read when the session ends; it owns the queue with the session.
class ControlInput {
public:
  explicit ControlInput(std::shared_ptr<Wake> W) : Q(std::make_shared<Queue>()) {
    Q->W = std::move(W);
    std::thread([Q = Q] { read(*Q); }).detach();
  }
  /// A command or the end of the input is waiting.
  bool pending() {
    std::lock_guard<std::mutex> Lock(Q->M);
    return !Q->Lines.empty() || Q->State != LineRead::Line;
  }
  /// The commands read so far; End: how the input ended after them (Line: it did not), and
  /// the number of the line that ended it.
  std::deque<Command> take(LineRead &End, unsigned &EndLine) {
    std::lock_guard<std::mutex> Lock(Q->M);
    std::deque<Command> Out;
    Out.swap(Q->Lines);
    End = Q->State;
    EndLine = Q->EndLine;
    return Out;
  }

private:
  struct Queue {
    std::mutex M;
    std::shared_ptr<Wake> W;
    std::deque<Command> Lines;
    LineRead State = LineRead::Line;
    unsigned EndLine = 0;
  };
  static void read(Queue &Q) {
    // SIGINT and SIGTERM go to the render loop's thread, never interrupt this read.
    sigset_t Signals;
    sigemptyset(&Signals);
    sigaddset(&Signals, SIGINT);
    sigaddset(&Signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &Signals, nullptr);
    std::string Line;
    for (unsigned N = 1;; ++N) {
      LineRead Got = readBoundedLine(std::cin, Line, MaxEditLine);
      {
        std::lock_guard<std::mutex> Lock(Q.M);
        if (Got == LineRead::Line) {
          Q.Lines.push_back({Line, nowSeconds(), N});
        } else {
          Q.State = Got;
          Q.EndLine = N;
        }
      }
      Q.W->notify();
      if (Got != LineRead::Line)
        return;
    }
  }
  std::shared_ptr<Queue> Q;
};

/// The edit schema of the graph rendered now (G, the live editor's) with its kernel's manifest
/// (Lay): per node its id, fn, file, return type and inputs (name, type, what feeds it:
/// "value", "node", "attr" or "image"; the parameter table's "default", "range", "min", "max"
/// and "doc"), and the nodes each material uses. The 'ready' and 'reload' events carry it
/// (docs/live.md).
ordered_json editSchema(const Layout &Lay, const texcc::graph::Graph &G);
/// The schema entry of input ARG of node NODE in G (null when its function has no such
/// parameter): the 'applied' event carries it, so that a front end replaces its copy of the
/// input with texrender's rather than applying the edit itself.
ordered_json inputSchema(const Layout &Lay, const texcc::graph::Graph &G, const std::string &Node,
                         const std::string &Arg);

/// A digest of graph.json's text: whether the file changed since it was last read.
inline size_t fileDigest(const std::string &Text) { return std::hash<std::string>{}(Text); }

/// texcc on the saved files, on a thread of its own (Regeneration::start), while the current
/// kernel renders.
struct SourceJob {
  std::shared_ptr<Regeneration> Run;
  size_t FileDigest = 0; // graph.json's when it started
  double Started = 0;
  // Only source files changed (graph.json as before): the control channel's edits are applied
  // again to the new kernel.
  bool KeepEdits = false;
};

class Session {
public:
  Session(WatchOptions Opts, const Layout &Initial) : O(std::move(Opts)), Lay(Initial) {
    O.Renderer.AfterPass = [this](const PassProgress &P) { return afterPass(P); };
    O.Renderer.CutPass = [this] { return cutPass(); };
    GraphPath = fs::absolute(Lay.GraphPath).string();
    FileDigest = fileDigest(readGraphFile(GraphPath));
  }
  ~Session() {
    Job.reset(); // joins texcc's thread
    if (Prime.joinable())
      Prime.join();
  }
  WatchResult run();

private:
  bool stopping() const { return O.Stop && O.Stop->load(); }
  bool jobDone() const { return Job && Job->Run->done(); }
  bool commandsPending() const { return Input && Input->pending(); }
  /// Something to do besides rendering: a file change, texcc done, a command, a shape kernel
  /// built in the background.
  bool work() { return !Changed.empty() || jobDone() || commandsPending() || tierBuilt(); }
  /// True once when a background build that frames switch to (a new kernel) has ended since
  /// the last look (TierEvent Built or Failed): accumulation restarts so that the faster kernel
  /// takes over. Takes the tier manager's ended builds (TierManager::collect, nothing adopted).
  bool tierBuilt();
  /// Subscribes the session to the tier manager's events of Into (and its wake-up): what
  /// tierBuilt answers, the lines said when a background build is done (onTierEvent).
  void followTiers(Renderer &Into);
  void onTierEvent(const TierEvent &E);
  /// A change to apply: a saved file, texcc done, a command.
  bool changePending() const { return !Changed.empty() || jobDone() || commandsPending(); }
  /// After the renderer's first complete frame (once per renderer: a scene reload makes a new
  /// OpenCL context): builds a tiny program from source on a thread of its own, so that the
  /// OpenCL implementation loads its compiler then rather than at the first saved source file
  /// (PoCL: about 1.3 s of the first build from source in a process, load 11; docs/live.md). A
  /// session whose kernels all came from the caches has built nothing yet.
  void primeCompiler();
  /// Before a regenerated kernel is built: the priming still running is waited for (the build
  /// would otherwise load the compiler itself); says how it went, for the "source change" line.
  std::string waitForPrime();
  /// After a change that regenerated the kernel (noticed at Since): if the quick tier renders
  /// it, says that the shape kernel builds behind it, and the takeover is timed from Since.
  void noteQuickTier(double Since);
  /// After a full-resolution pass: starts the shape kernel held behind the quick tier.
  void fullPassDone();
  /// Renders with all the samples (stopped early by work()), writing progress images.
  void renderFrame();
  /// A texture fault (a loop past its budget, an out-of-bounds read) of the state being
  /// rendered: reported on stderr and as an error event, then the last good state (the kernel,
  /// graph and edits of the last frame completed without a fault) renders again. Without one
  /// (or when that state faults too), rendering waits for the next change (WatchFrames.cpp).
  void recoverFromFault(const TextureFault &X);
  /// R->render(Stats), then Restore() (the settings or state the pass changed), whether the
  /// render returned or threw.
  std::vector<float> renderThen(FrameStats &Stats, const std::function<void()> &Restore);
  /// The first image after a change: one sample per pixel at 1/F of the width and height
  /// (PassTimes::factor; WatchOptions::ReducedFirstPass).
  void reducedPass();
  bool afterPass(const PassProgress &P);
  /// RendererOptions::CutPass: a full-resolution pass in flight is abandoned when there is work
  /// (an edit, a saved file): its accumulation restarts anyway.
  bool cutPass();
  /// Waits for work at most until the next poll of the files (and Until, if given).
  void idle(double Until = 0);
  void poll();
  void watchFiles();
  /// Image: Width x Height (0: the output's size); Factor: the reduction of a reduced pass's
  /// image (1: full resolution).
  void writeProgress(const std::vector<float> &Image, int Spp, int Factor = 1, int Width = 0,
                     int Height = 0);
  void applyChanges();
  /// Changed: the graph's source files that changed (empty: only the graph did).
  void applyGraph(const std::set<std::string> &Changed);
  /// A saved graph.json's diff, applied to the live editor and the renderer: all or nothing.
  void applyEdits(const std::vector<texcc::graph::Edit> &Edits);
  void startJob(const std::string &What, bool KeepEdits);
  void adoptJob();
  /// Applies the edits that take the live editor's graph to Edited (the graph rendered with the
  /// old kernel: the control channel's edits, kept over a new kernel) to the live editor and
  /// the renderer; one that no longer applies is reported and dropped.
  void applyKeptEdits(const texcc::graph::Graph &Edited);
  void reloadScene();
  void handleCommands();
  void handleCommand(const Command &C);
  /// One JSON event a line on standard output (--control only).
  void event(const ordered_json &E);
  /// A saved change is applied (What: scene, graph or source): the reload event, with the
  /// edit schema of the graph rendered now (--control only).
  void reloadEvent(const std::string &What);
  /// An error event (--control only); Id: the command's, if it was one.
  void errorEvent(const std::string &Message, std::optional<long long> Id = std::nullopt);
  unsigned buildsSoFar() const { return R->cl().foregroundBuilds() + R->cl().backgroundBuilds(); }

  WatchOptions O;
  Layout Lay;
  std::unique_ptr<Renderer> R;
  std::unique_ptr<LiveEditor> Editor;
  std::unique_ptr<ControlInput> Input;
  std::string GraphPath;
  // Makes every regeneration of this session's kernel (saved files here, edits in Editor).
  std::shared_ptr<const Regenerator> Regen = std::make_shared<const Regenerator>();
  // The folders of the kernels texcc made for this session: kept until it ends (the last good
  // state, a fallback built later, may read their files).
  std::vector<std::shared_ptr<const TempFolder>> Folders;
  // The graph rendered now is the live editor's (Editor->graph()); of graph.json the session
  // keeps only the digest of the text last read (a source saved beside an unchanged graph.json
  // keeps the control channel's edits).
  size_t FileDigest = 0;
  FileWatcher Files;
  std::set<std::string> Changed;
  std::unique_ptr<SourceJob> Job;
  std::thread Prime;         // primeCompiler's build
  bool Primed = false;       // primeCompiler ran for R (its thread may still be running)
  double PrimeSeconds = 0;   // its time, set by its thread (read after joining it)
  // Wakes idle(): control lines, texcc done.
  std::shared_ptr<Wake> Waker = std::make_shared<Wake>();
  bool JobAgain = false, Ended = false, Ok = true;
  unsigned Frames = 0;
  // Noticed: when the change being applied was seen; ChangeAt: when the change whose first
  // refined frame is awaited was seen (0: none; set once a change is applied, not on an error).
  double Noticed = 0, ChangeAt = 0, LastWrite = 0, LastPoll = 0;
  // The control channel: the last edit applied, and when the line of the one whose first
  // refined frame is awaited was read (0: none).
  std::optional<long long> LastEdit;
  double EditAt = 0;
  // Where an edit's latency goes (the frame event's "split"): its line read (EditAt), the
  // render loop free to handle it, the edit applied, the pass that shows it started and done.
  double HandledAt = 0, AppliedAt = 0, PassStart = 0, PassEnd = 0;
  bool TierSwitch = false;
  // Where the first frame of a kernel regenerated by texcc went (the frame event's "source" and
  // the "source change: ..." line): the change noticed (Regeneration::Started), texcc done, the
  // kernel adopted (Renderer::setLayout: its foreground program loads, builds and warm-ups,
  // BuildMs of it; Builds: those built from source). Adopted == 0: none awaited.
  struct SourceSplit {
    double Noticed = 0, TexccDone = 0, AdoptStart = 0, Adopted = 0, BuildMs = 0;
    unsigned Builds = 0;
    std::string Primed; // waitForPrime's account
  };
  SourceSplit Source;
  // When the change that the quick tier renders was noticed, until the shape kernel built
  // behind it takes over (0: none; noteQuickTier).
  double QuickSince = 0;
  // What is rendered changed since the last complete frame (an edit, a reload, a new kernel).
  bool Dirty = true;
  // Accumulations started (one per render()) and the last one written, with its samples: a
  // frame is written once.
  unsigned Accumulation = 0, WrittenAccumulation = 0;
  int WrittenSpp = 0;
  // Pass times by pixel count, for the reduced pass's factor; when the pass being timed began
  // or the renderer was handed back by afterPass; a full-resolution pass may be cut.
  PassTimes Times;
  // The last good state (recoverFromFault): what the last frame completed without a texture
  // fault rendered (its kernel is told apart by its folder, Layout::Dir: texcc's output for
  // each regeneration has its own).
  struct GoodState {
    Layout Lay;
    texcc::graph::Graph Graph;
  };
  std::optional<GoodState> Good;
  bool RenderingGood = false; // the good state was restored after a fault and has not completed
  double PassResume = 0;
  bool Cuttable = false;
  unsigned PassesCut = 0;
  unsigned PassesInFrame = 0; // full-resolution passes done in the frame being rendered
  bool HoldPass = [] {
    const char *E = std::getenv("TEXRENDER_HOLD_PASS");
    return E && *E && std::string(E) != "0";
  }();
};

} // namespace watch
} // namespace texrender

#endif
