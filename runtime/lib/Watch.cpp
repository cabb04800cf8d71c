// texrender --watch: the progressive render loop and the file watcher (Watch.h, docs/live.md).
#include "texrender/Watch.h"

#include "texrender/Error.h"
#include "texrender/Image.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <signal.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

namespace texrender {

LineRead readBoundedLine(std::istream &In, std::string &Line, size_t Max) {
  Line.clear();
  std::streambuf *Buf = In.rdbuf();
  for (bool Any = false;; Any = true) {
    int C = Buf->sbumpc();
    if (C == std::char_traits<char>::eof())
      return Any ? LineRead::Line : LineRead::End;
    if (C == '\n')
      return LineRead::Line;
    if (Line.size() == Max)
      return LineRead::TooLong;
    Line.push_back(char(C));
  }
}

FileWatcher::Seen FileWatcher::look(const std::string &Path) {
  Seen S;
  S.Path = Path;
  struct stat St;
  if (::stat(Path.c_str(), &St) == 0) {
    S.Exists = true;
    S.Size = St.st_size;
    S.MTimeNs = (long long)St.st_mtim.tv_sec * 1000000000LL + St.st_mtim.tv_nsec;
  }
  return S;
}

void FileWatcher::watch(const std::vector<std::string> &Paths) {
  std::vector<Seen> Next;
  for (const std::string &P : Paths) {
    auto Old = std::find_if(Files.begin(), Files.end(), [&](const Seen &S) { return S.Path == P; });
    Next.push_back(Old != Files.end() ? *Old : look(P));
  }
  Files = std::move(Next);
}

std::vector<std::string> FileWatcher::changed() {
  std::vector<std::string> Out;
  for (Seen &S : Files) {
    Seen Now = look(S.Path);
    if (Now.Exists != S.Exists || Now.Size != S.Size || Now.MTimeNs != S.MTimeNs)
      Out.push_back(S.Path);
    S = Now;
  }
  return Out;
}

std::vector<std::string> graphFiles(const std::string &GraphPath, const json &Graph) {
  std::vector<std::string> Out{GraphPath};
  fs::path Dir = fs::path(GraphPath).parent_path();
  if (Graph.is_object() && Graph.contains("sources") && Graph["sources"].is_array())
    for (const json &S : Graph["sources"])
      if (S.is_string())
        Out.push_back((Dir / S.get<std::string>()).lexically_normal().string());
  return Out;
}

std::optional<std::vector<std::string>> argumentEdits(const json &Old, const json &New) {
  if (!Old.is_object() || !New.is_object())
    return std::nullopt;
  for (auto It = New.begin(); It != New.end(); ++It)
    if (It.key() != "nodes" && (!Old.contains(It.key()) || Old[It.key()] != It.value()))
      return std::nullopt;
  for (auto It = Old.begin(); It != Old.end(); ++It)
    if (!New.contains(It.key()))
      return std::nullopt;
  const json &ON = Old.value("nodes", json::array()), &NN = New.value("nodes", json::array());
  if (!ON.is_array() || !NN.is_array() || ON.size() != NN.size())
    return std::nullopt;
  std::vector<std::string> Edits;
  for (size_t I = 0; I < ON.size(); ++I) {
    const json &A = ON[I], &B = NN[I];
    if (!A.is_object() || !B.is_object() || A.size() != B.size())
      return std::nullopt;
    for (auto It = B.begin(); It != B.end(); ++It)
      if (It.key() != "args" && (!A.contains(It.key()) || A[It.key()] != It.value()))
        return std::nullopt;
    const json &AA = A.value("args", json::object()), &BA = B.value("args", json::object());
    if (!AA.is_object() || !BA.is_object() || AA.size() != BA.size() || !B["id"].is_string())
      return std::nullopt;
    for (auto It = BA.begin(); It != BA.end(); ++It) {
      if (!AA.contains(It.key()))
        return std::nullopt;
      if (AA[It.key()] != It.value())
        Edits.push_back("set " + B["id"].get<std::string>() + "." + It.key() + "=" + It.value().dump());
    }
  }
  return Edits;
}

void PassTimes::record(double Pixels, double Seconds) {
  auto It = std::find_if(Sizes.begin(), Sizes.end(), [&](const Size &S) { return S.Pixels == Pixels; });
  if (It != Sizes.end()) {
    It->Seconds = 0.5 * It->Seconds + 0.5 * Seconds;
    It->Seq = ++Seq;
    return;
  }
  Sizes.push_back({Pixels, Seconds, ++Seq});
  if (Sizes.size() > 4)
    Sizes.erase(std::min_element(Sizes.begin(), Sizes.end(),
                                 [](const Size &A, const Size &B) { return A.Seq < B.Seq; }));
}

double PassTimes::predict(double Pixels) const {
  if (Sizes.empty())
    return -1;
  const double N = double(Sizes.size());
  double SP = 0, ST = 0, SPP = 0, SPT = 0, MaxT = 0;
  for (const Size &S : Sizes) {
    SP += S.Pixels, ST += S.Seconds, SPP += S.Pixels * S.Pixels, SPT += S.Pixels * S.Seconds;
    MaxT = std::max(MaxT, S.Seconds);
  }
  // Least squares: Seconds = Fixed + PerPixel * Pixels.
  double Var = SPP - SP * SP / N;
  double PerPixel = Var > 0 ? (SPT - SP * ST / N) / Var : 0, Fixed = (ST - PerPixel * SP) / N;
  if (Var <= 0 || Fixed < 0) // one size, or noise: through the origin
    Fixed = 0, PerPixel = SPT / SPP;
  if (PerPixel <= 0) // smaller passes took longer (noise): no size is predicted to be faster
    return MaxT;
  return Fixed + PerPixel * Pixels;
}

int PassTimes::factor(int Width, int Height, double Budget) const {
  if (Sizes.empty())
    return 2;
  int F = 2;
  for (; F < 16 && ((Width + F - 1) / F > 1 || (Height + F - 1) / F > 1); F *= 2) {
    double Pixels = double((Width + F - 1) / F) * double((Height + F - 1) / F);
    if (predict(Pixels) <= Budget)
      return F;
  }
  return F;
}

namespace {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void say(const std::string &Line) {
  std::fprintf(stderr, "texrender: watch: %s\n", Line.c_str());
  std::fflush(stderr);
}

std::string ms(double Seconds) { return std::to_string(int(Seconds * 1000 + 0.5)) + " ms"; }

/// Milliseconds rounded to 0.01, for the control channel's events.
double eventMs(double Seconds) { return std::round(Seconds * 1e5) / 100; }

/// After a reduced first pass, full-resolution rendering starts once no change has come for
/// this long (docs/live.md).
constexpr double ReducedPause = 0.25;

/// A line of standard input, as the control channel's thread read it.
struct Command {
  std::string Text;
  double ReadAt = 0; // when its newline arrived (the edit's latency counts from there)
  unsigned LineNo = 0;
};

/// --control's standard input. A thread reads the lines (bounded, as --interactive does) into a
/// queue, so that a command is timed when it arrives rather than when the render loop gets to
/// it, and the idle loop wakes at once. The thread is detached: it may stay blocked in a read
/// when the session ends; it owns the queue with the session.
class ControlInput {
public:
  ControlInput() : Q(std::make_shared<Queue>()) {
    std::thread([Q = Q] { read(*Q); }).detach();
  }
  /// A command or the end of the input is waiting.
  bool pending() {
    std::lock_guard<std::mutex> Lock(Q->M);
    return !Q->Lines.empty() || Q->State != LineRead::Line;
  }
  /// Waits at most Ms milliseconds for pending().
  void waitFor(int Ms) {
    std::unique_lock<std::mutex> Lock(Q->M);
    Q->Wake.wait_for(Lock, std::chrono::milliseconds(Ms),
                     [this] { return !Q->Lines.empty() || Q->State != LineRead::Line; });
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
    std::condition_variable Wake;
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
      std::lock_guard<std::mutex> Lock(Q.M);
      if (Got == LineRead::Line) {
        Q.Lines.push_back({Line, nowSeconds(), N});
      } else {
        Q.State = Got;
        Q.EndLine = N;
      }
      Q.Wake.notify_all();
      if (Got != LineRead::Line)
        return;
    }
  }
  std::shared_ptr<Queue> Q;
};

/// Applies E to the graph G (graph.json's model) as the live editor applies it to its own copy,
/// so that a scene reload or a recompiled source file can apply the control channel's edits
/// again (argumentEdits). E has been applied by the live editor, so its value parses.
void applyToGraphJson(json &G, const Edit &E) {
  if (!G.contains("nodes") || !G["nodes"].is_array())
    return;
  for (json &N : G["nodes"]) {
    if (!N.is_object() || N.value("id", "") != E.Node)
      continue;
    json &Args = N["args"];
    if (E.K == Edit::Kind::Rewire) {
      Args[E.Arg] = json{{"node", E.Value}};
      continue;
    }
    json Value = json::parse(E.Value);
    if (Args.contains(E.Arg) && Args[E.Arg].is_object() && Args[E.Arg].value("bake", false))
      Args[E.Arg]["value"] = Value;
    else
      Args[E.Arg] = Value;
  }
}

/// texcc on the changed graph, on a thread of its own, while the current kernel renders.
struct Regeneration {
  std::thread Thread;
  std::atomic<bool> Done{false};
  std::optional<Layout> Result;
  std::string Log;   // texcc's diagnostics when it failed
  json Graph;
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
    Graph = LayGraph = FileGraph = json::parse(readWholeFile(GraphPath, " graph"));
    TempRoot = (fs::temp_directory_path() / ("texrender-watch-" + std::to_string(::getpid()))).string();
    fs::create_directories(TempRoot);
  }
  ~Session() {
    if (Job && Job->Thread.joinable())
      Job->Thread.join();
    std::error_code EC;
    fs::remove_all(TempRoot, EC);
  }
  WatchResult run();

private:
  bool stopping() const { return O.Stop && O.Stop->load(); }
  bool jobDone() const { return Job && Job->Done.load(); }
  bool commandsPending() const { return Input && Input->pending(); }
  /// Something to do besides rendering: a file change, texcc done, a command, a shape kernel
  /// built in the background.
  bool work() { return !Changed.empty() || jobDone() || commandsPending() || tierBuilt(); }
  /// True once when the background build of a tier (shape mode, tier auto) has finished since
  /// the last look: accumulation restarts so that the faster kernel takes over.
  bool tierBuilt();
  /// A change to apply: a saved file, texcc done, a command.
  bool changePending() const { return !Changed.empty() || jobDone() || commandsPending(); }
  /// Renders with all the samples (stopped early by work()), writing progress images.
  void renderFrame();
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
  void applyEdits(const std::vector<std::string> &Lines, const json &New);
  void startJob(const json &New, const std::string &What, bool KeepEdits);
  void adoptJob();
  /// Applies the edits that take LayGraph to Edited (the control channel's, kept over a new
  /// kernel or scene) to the live editor and the renderer; one that no longer applies is
  /// reported and dropped.
  void applyKeptEdits(const json &Edited);
  void reloadScene();
  void handleCommands();
  void handleCommand(const Command &C);
  /// One JSON event a line on standard output (--control only).
  void event(const ordered_json &E);
  /// An error event (--control only); Id: the command's, if it was one.
  void errorEvent(const std::string &Message, std::optional<long long> Id = std::nullopt);
  unsigned buildsSoFar() const { return R->cl().foregroundBuilds() + R->cl().backgroundBuilds(); }

  WatchOptions O;
  Layout Lay;
  std::unique_ptr<Renderer> R;
  std::unique_ptr<LiveEditor> Editor;
  std::unique_ptr<ControlInput> Input;
  std::string GraphPath, TempRoot;
  json Graph;     // the graph rendered now: LayGraph plus the live edits applied since
  json LayGraph;  // the graph Lay was compiled from
  json FileGraph; // graph.json as last read
  FileWatcher Files;
  std::set<std::string> Changed;
  std::unique_ptr<Regeneration> Job;
  bool JobAgain = false, Ended = false, Ok = true;
  unsigned Generation = 0, Frames = 0;
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
  bool TierPending = false, TierSwitch = false;
  // What is rendered changed since the last complete frame (an edit, a reload, a new kernel).
  bool Dirty = true;
  // Accumulations started (one per render()) and the last one written, with its samples: a
  // frame is written once.
  unsigned Accumulation = 0, WrittenAccumulation = 0;
  int WrittenSpp = 0;
  // Pass times by pixel count, for the reduced pass's factor; when the pass being timed began
  // or the renderer was handed back by afterPass; a full-resolution pass may be cut.
  PassTimes Times;
  double PassResume = 0;
  bool Cuttable = false;
  unsigned PassesCut = 0;
};

void Session::event(const ordered_json &E) {
  if (!O.Control)
    return;
  std::string Line = E.dump(-1, ' ', false, json::error_handler_t::replace);
  Line += '\n';
  std::fwrite(Line.data(), 1, Line.size(), stdout);
  std::fflush(stdout);
}

void Session::errorEvent(const std::string &Message, std::optional<long long> Id) {
  ordered_json E{{"event", "error"}};
  if (Id)
    E["id"] = *Id;
  std::string M = Message;
  while (!M.empty() && M.back() == '\n')
    M.pop_back();
  E["message"] = M;
  event(E);
}

void Session::watchFiles() {
  std::vector<std::string> Paths = graphFiles(GraphPath, Graph);
  Paths.push_back(fs::absolute(O.ScenePath).string());
  Files.watch(Paths);
}

void Session::poll() {
  LastPoll = nowSeconds();
  for (const std::string &P : Files.changed())
    Changed.insert(P);
}

void Session::idle(double Until) {
  double End = LastPoll + 0.1;
  if (Until > 0)
    End = std::min(End, Until);
  int Left = std::max(1, int((End - nowSeconds()) * 1000));
  if (Input)
    Input->waitFor(Left);
  else
    std::this_thread::sleep_for(std::chrono::milliseconds(Left));
  if (nowSeconds() - LastPoll >= 0.1)
    poll();
}

bool Session::tierBuilt() {
  bool Pending = R->backgroundBuildPending();
  if (TierPending && !Pending)
    TierSwitch = true;
  TierPending = Pending;
  return TierSwitch;
}

void Session::reducedPass() {
  RenderSettings &S = R->settings();
  if (S.RegionWidth != 0 || O.Width < 2 || O.Height < 2)
    return;
  const RenderSettings Saved = S;
  const int F = Times.factor(O.Width, O.Height, O.FirstPassBudget);
  const int W = (O.Width + F - 1) / F, H = (O.Height + F - 1) / F;
  S.Width = W, S.Height = H, S.Spp = 1;
  FrameStats Stats;
  PassStart = nowSeconds();
  std::vector<float> Small;
  try {
    Small = R->render(Stats);
  } catch (...) {
    S = Saved;
    throw;
  }
  S = Saved;
  PassEnd = nowSeconds();
  Times.record(double(W) * H, PassEnd - PassStart);
  if (stopping())
    return;
  if (O.Control) // the front end scales it up
    return writeProgress(Small, 1, F, W, H);
  // Each pixel of the reduced image covers FxF pixels of the image written.
  std::vector<float> Image(size_t(O.Width) * O.Height * 3);
  for (int Y = 0; Y < O.Height; ++Y)
    for (int X = 0; X < O.Width; ++X)
      for (int C = 0; C < 3; ++C)
        Image[(size_t(Y) * O.Width + X) * 3 + C] = Small[(size_t(Y / F) * W + X / F) * 3 + C];
  writeProgress(Image, 1, F);
}

/// Writes the image (atomically: writeImage renames a finished file into place) and, for the
/// first image after a change, reports the change-to-refined-frame latency.
void Session::writeProgress(const std::vector<float> &Image, int Spp, int Factor, int Width,
                            int Height) {
  const bool Reduced = Factor > 1;
  if (!Reduced && Accumulation == WrittenAccumulation && Spp == WrittenSpp)
    return;
  if (Width == 0)
    Width = O.Width, Height = O.Height;
  double WriteStart = nowSeconds();
  writePreviewImage(O.Output, Width, Height, Image);
  LastWrite = nowSeconds();
  WrittenAccumulation = Accumulation;
  WrittenSpp = Spp;
  std::string Tier = R->activeTier().empty() ? std::string("-") : R->activeTier();
  if (ChangeAt > 0) {
    say("first refined frame " + ms(LastWrite - ChangeAt) + " after the change (tier " + Tier + ")");
    ChangeAt = 0;
  }
  ordered_json E{{"event", "frame"},     {"path", fs::absolute(O.Output).string()},
                 {"width", Width},       {"height", Height},
                 {"spp", Spp},           {"tier", Tier},
                 {"builds", buildsSoFar()}, {"edit", nullptr},
                 {"latency_ms", nullptr}};
  if (LastEdit)
    E["edit"] = *LastEdit;
  if (Reduced) {
    E["reduced"] = true;
    E["factor"] = Factor;
  }
  if (EditAt > 0) {
    E["latency_ms"] = eventMs(LastWrite - EditAt);
    E["split"] = ordered_json{{"wait_ms", eventMs(HandledAt - EditAt)},
                              {"apply_ms", eventMs(AppliedAt - HandledAt)},
                              {"to_pass_ms", eventMs(PassStart - AppliedAt)},
                              {"pass_ms", eventMs(PassEnd - PassStart)},
                              {"write_ms", eventMs(LastWrite - WriteStart)}};
    say("edit " + std::to_string(LastEdit ? *LastEdit : -1) + ": first frame " +
        ms(LastWrite - EditAt) + " after its line was read: waited " + ms(HandledAt - EditAt) +
        " for the pass in flight, applied in " + ms(AppliedAt - HandledAt) + ", " +
        (Reduced ? "reduced pass (1/" + std::to_string(Factor) + ") " : std::string("pass ")) +
        ms(PassEnd - PassStart) + ", image written in " +
        ms(LastWrite - WriteStart));
    EditAt = 0;
  }
  event(E);
}

bool Session::cutPass() {
  if (!Cuttable)
    return false;
  if (nowSeconds() - LastPoll >= 0.1)
    poll();
  return !stopping() && work();
}

bool Session::afterPass(const PassProgress &P) {
  double Now = nowSeconds();
  PassEnd = Now;
  Times.record(double(O.Width) * O.Height, Now - PassResume);
  // The first image after a change is written at once; the others at most 4 times a second.
  if (Now - LastWrite >= 0.25 || ChangeAt > 0 || EditAt > 0)
    writeProgress(P.Image(), P.SamplesDone);
  if (Now - LastPoll >= 0.1)
    poll();
  PassResume = nowSeconds();
  return !stopping() && !work();
}

WatchResult Session::run() {
  R = std::make_unique<Renderer>(O.LoadScene(), Lay, O.Renderer);
  Editor = std::make_unique<LiveEditor>(Lay);
  watchFiles();
  say("watching " + GraphPath + ", its sources and " + O.ScenePath + "; Ctrl-C ends");
  if (O.Control) {
    ordered_json Sources = json::array();
    for (const std::string &S : graphFiles(GraphPath, Graph))
      if (S != GraphPath)
        Sources.push_back(S);
    event({{"event", "ready"}, {"graph", GraphPath}, {"sources", Sources},
           {"width", O.Width}, {"height", O.Height}});
    Input = std::make_unique<ControlInput>();
  }
  while (!stopping() && !Ended) {
    // A change that came during the reduced pass or the pause after it is handled first. A
    // complete frame is not rendered again until something it shows changed (texcc running
    // in the background changes nothing yet).
    if (!changePending()) {
      if (Dirty || TierSwitch)
        renderFrame();
      else
        while (!stopping() && !work())
          idle();
    }
    if (stopping())
      break;
    if (jobDone())
      adoptJob();
    if (!Changed.empty())
      applyChanges();
    if (commandsPending())
      handleCommands();
    if (O.ReducedFirstPass && (EditAt > 0 || ChangeAt > 0) && !stopping() && !Ended) {
      reducedPass();
      // While edits keep coming (a slider dragged) the next one meets no full-resolution pass
      // in flight: full resolution starts after a pause without changes.
      double Until = nowSeconds() + ReducedPause;
      while (!stopping() && !work() && nowSeconds() < Until)
        idle(Until);
    }
  }
  return {Frames, Ok};
}

void Session::renderFrame() {
  FrameStats F;
  ++Accumulation;
  if (TierSwitch) {
    TierSwitch = false;
    say("the background build is done: accumulation restarts with its kernel");
  }
  PassStart = PassResume = nowSeconds();
  Cuttable = true;
  std::vector<float> Image;
  try {
    Image = R->render(F);
  } catch (...) {
    Cuttable = false;
    throw;
  }
  Cuttable = false;
  if ((!F.Interrupted || stopping()) && F.SamplesDone > 0)
    writeProgress(Image, F.SamplesDone);
  if (F.PassCut)
    say("pass " + std::to_string(F.SamplesDone + 1) + " cut short after " +
        ms(nowSeconds() - PassResume) + " for a change (" + std::to_string(++PassesCut) +
        " so far)");
  if (F.Interrupted)
    return;
  Dirty = false;
  ++Frames;
  say("frame " + std::to_string(Frames) + ": " + std::to_string(F.SamplesDone) + " spp in " +
      ms(F.Seconds) + ", tier " + (F.Tier.empty() ? std::string("-") : F.Tier) +
      "; kernel builds so far " + std::to_string(R->cl().foregroundBuilds()));
  while (!stopping() && !work())
    idle();
}

void Session::handleCommands() {
  HandledAt = nowSeconds();
  LineRead End;
  unsigned EndLine;
  for (const Command &C : Input->take(End, EndLine)) {
    if (Ended)
      return;
    handleCommand(C);
  }
  if (End == LineRead::TooLong) {
    std::string M = "standard input:" + std::to_string(EndLine) + ": line longer than " +
                    std::to_string(MaxEditLine) + " bytes; the control session ends";
    std::fprintf(stderr, "texrender: error: %s\n", M.c_str());
    errorEvent(M);
    Ok = false;
  }
  if (End != LineRead::Line)
    Ended = true;
}

/// "ID EDIT" (an edit line of --interactive's syntax: set or rewire) or "quit".
void Session::handleCommand(const Command &C) {
  size_t B = C.Text.find_first_not_of(" \t\r");
  if (B == std::string::npos || C.Text[B] == '#')
    return;
  size_t E = B;
  while (E < C.Text.size() && std::isdigit((unsigned char)C.Text[E]))
    ++E;
  std::optional<long long> Id;
  if (E > B && E - B <= 15 && E < C.Text.size() && (C.Text[E] == ' ' || C.Text[E] == '\t')) {
    Id = std::stoll(C.Text.substr(B, E - B));
    B = C.Text.find_first_not_of(" \t", E);
  }
  std::string Rest = B == std::string::npos ? "" : C.Text.substr(B);
  while (!Rest.empty() && (Rest.back() == '\r' || Rest.back() == ' ' || Rest.back() == '\t'))
    Rest.pop_back();
  if (Rest == "quit") {
    say("quit");
    Ended = true;
    return;
  }
  auto refuse = [&](const std::string &M) {
    std::fprintf(stderr, "texrender: watch: error: %s; nothing applied\n", M.c_str());
    std::fflush(stderr);
    errorEvent(M, Id);
  };
  if (!Id)
    return refuse("standard input:" + std::to_string(C.LineNo) +
                  ": expected 'ID EDIT' (a decimal id, then set NODE.ARG=VALUE or rewire "
                  "NODE.ARG=SOURCE) or 'quit', got '" + Rest + "'");
  Edit Ed;
  try {
    Ed = parseEdit(Rest);
  } catch (const Error &X) {
    return refuse(X.what());
  }
  if (Ed.K == Edit::Kind::Wait)
    return refuse("edit 'wait': the control channel takes set and rewire edits");
  if (std::optional<EditProblem> P = Editor->check({Ed}))
    return refuse("edit '" + Ed.Text + "': " + P->Message);
  unsigned Builds = R->cl().foregroundBuilds();
  double T0 = nowSeconds();
  try {
    Editor->apply(Ed, *R);
  } catch (const Error &X) {
    return refuse(X.what());
  }
  double Took = nowSeconds() - T0;
  applyToGraphJson(Graph, Ed);
  unsigned Built = R->cl().foregroundBuilds() - Builds;
  LastEdit = Id;
  Dirty = true;
  EditAt = C.ReadAt;
  AppliedAt = nowSeconds();
  say("applied '" + Ed.Text + "' (id " + std::to_string(*Id) + ") in " + ms(Took) + ", " +
      std::to_string(Built) + " kernel build(s)");
  event({{"event", "applied"}, {"id", *Id}, {"ms", eventMs(Took)}, {"builds", Built}});
}

void Session::applyChanges() {
  std::set<std::string> Now;
  Now.swap(Changed);
  Noticed = nowSeconds();
  std::string Scene = fs::absolute(O.ScenePath).string();
  bool SceneChanged = Now.erase(Scene) > 0;
  bool GraphChanged = Now.erase(GraphPath) > 0;
  if (SceneChanged) {
    event({{"event", "reload"}, {"what", "scene"}});
    reloadScene();
  }
  if (GraphChanged || !Now.empty()) {
    event({{"event", "reload"}, {"what", Now.empty() ? "graph" : "source"}});
    applyGraph(Now);
  }
}

void Session::applyKeptEdits(const json &Edited) {
  std::optional<std::vector<std::string>> Edits = argumentEdits(LayGraph, Edited);
  if (!Edits)
    return;
  for (const std::string &Text : *Edits) {
    try {
      Edit E = parseEdit(Text);
      if (std::optional<EditProblem> P = Editor->check({E}))
        throw Error("edit '" + E.Text + "': " + P->Message);
      Editor->apply(E, *R);
      applyToGraphJson(Graph, E);
    } catch (const Error &X) {
      say("error: " + std::string(X.what()) + "; this edit is dropped");
      errorEvent(std::string(X.what()) + "; this edit is dropped");
    }
  }
}

void Session::reloadScene() {
  try {
    auto New = std::make_unique<Renderer>(O.LoadScene(), Lay, O.Renderer);
    // The new renderer has Lay's arguments: the live edits made since are applied again.
    auto NewEditor = std::make_unique<LiveEditor>(Lay);
    if (std::optional<std::vector<std::string>> Edits = argumentEdits(LayGraph, Graph))
      for (const std::string &E : *Edits)
        NewEditor->apply(parseEdit(E), *New);
    R = std::move(New);
    Editor = std::move(NewEditor);
    Dirty = true;
    ChangeAt = Noticed;
    say(O.ScenePath + " reloaded");
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good scene keeps rendering");
    errorEvent(std::string(E.what()));
  }
}

void Session::applyGraph(const std::set<std::string> &Sources) {
  json New;
  try {
    New = json::parse(readWholeFile(GraphPath, " graph"));
  } catch (const json::parse_error &E) {
    std::fprintf(stderr, "%s: error: %s\n", GraphPath.c_str(), E.what());
    say("the last good graph keeps rendering");
    errorEvent(GraphPath + ": error: " + E.what());
    return;
  } catch (const Error &E) {
    say("error: " + std::string(E.what()) + "; the last good graph keeps rendering");
    errorEvent(E.what());
    return;
  }
  bool GraphSame = New == FileGraph;
  FileGraph = New;
  std::optional<std::vector<std::string>> Edits;
  if (Sources.empty())
    Edits = argumentEdits(Graph, New);
  std::string What;
  for (const std::string &S : Sources)
    What += (What.empty() ? "" : ", ") + S;
  if (Edits)
    applyEdits(*Edits, New);
  else
    startJob(New, What.empty() ? GraphPath : What, GraphSame && !Sources.empty());
}

void Session::applyEdits(const std::vector<std::string> &Lines, const json &New) {
  if (Lines.empty()) {
    say(GraphPath + ": saved without a change to apply");
    Graph = New;
    return;
  }
  std::vector<Edit> Edits;
  try {
    for (const std::string &L : Lines)
      Edits.push_back(parseEdit(L));
  } catch (const Error &E) {
    std::fprintf(stderr, "%s: error: %s\n", GraphPath.c_str(), E.what());
    errorEvent(GraphPath + ": error: " + E.what());
    return;
  }
  if (std::optional<EditProblem> P = Editor->check(Edits)) {
    std::string M = GraphPath + ": error: edit '" + Edits[P->Index].Text + "': " + P->Message +
                    "; nothing applied";
    std::fprintf(stderr, "%s\n", M.c_str());
    errorEvent(M);
    return;
  }
  unsigned Builds = R->cl().foregroundBuilds();
  double T0 = nowSeconds();
  std::string Text;
  try {
    for (const Edit &E : Edits) {
      Editor->apply(E, *R);
      Text += (Text.empty() ? "" : "; ") + E.Text;
    }
  } catch (const Error &E) {
    std::fprintf(stderr, "%s: error: %s\n", GraphPath.c_str(), E.what());
    errorEvent(GraphPath + ": error: " + E.what());
    return;
  }
  Graph = New;
  Dirty = true;
  ChangeAt = Noticed;
  say("applied '" + Text + "' in " + ms(nowSeconds() - T0) + ", " +
      std::to_string(R->cl().foregroundBuilds() - Builds) + " kernel build(s)");
}

void Session::startJob(const json &New, const std::string &What, bool KeepEdits) {
  if (Job) {
    JobAgain = true; // the newest files are compiled once this run ends
    Job->KeepEdits = Job->KeepEdits && KeepEdits;
    return;
  }
  Job = std::make_unique<Regeneration>();
  Job->Graph = New;
  Job->Started = Noticed; // its latency is reported once its kernel is adopted
  Job->KeepEdits = KeepEdits;
  std::string Out = TempRoot + "/gen" + std::to_string(++Generation);
  say(What + " changed: texcc runs in the background; the current kernel keeps rendering");
  Regeneration *J = Job.get();
  Job->Thread = std::thread([J, Out, Graph = GraphPath, Options = Lay.CompileOptions] {
    try {
      J->Result = runTexcc(findTexcc(), Options, Graph, Out, Out + ".log");
    } catch (const std::exception &E) {
      std::error_code EC;
      J->Log = fs::exists(Out + ".log", EC) ? readWholeFile(Out + ".log") : std::string(E.what());
    }
    J->Done.store(true);
  });
}

void Session::adoptJob() {
  Job->Thread.join();
  std::unique_ptr<Regeneration> J = std::move(Job);
  if (JobAgain) {
    JobAgain = false;
    Noticed = J->Started;
    bool Keep = J->KeepEdits;
    applyGraph({GraphPath}); // files saved while it ran: compile them as they are now
    if (Job)
      Job->KeepEdits = Keep && FileGraph == J->Graph;
    return;
  }
  if (!J->Result) {
    std::fputs(J->Log.c_str(), stderr);
    if (!J->Log.empty() && J->Log.back() != '\n')
      std::fputc('\n', stderr);
    say("texcc failed: the last good kernel keeps rendering");
    errorEvent(J->Log);
    Dirty = true; // a new accumulation of the last good state shows that it is still there
    return;
  }
  unsigned Builds = R->cl().foregroundBuilds();
  try {
    R->setLayout(*J->Result);
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good kernel keeps rendering");
    errorEvent(E.what());
    return;
  }
  json Edited = Graph;
  Lay = *J->Result;
  Editor = std::make_unique<LiveEditor>(Lay);
  Graph = LayGraph = J->Graph;
  if (J->KeepEdits)
    applyKeptEdits(Edited);
  watchFiles();
  Dirty = true;
  ChangeAt = J->Started;
  say("new kernel from texcc after " + ms(nowSeconds() - J->Started) + ", " +
      std::to_string(R->cl().foregroundBuilds() - Builds) + " kernel build(s) waited for");
}

} // namespace

WatchResult runWatch(WatchOptions O, const Layout &Initial) {
  Session S(std::move(O), Initial);
  return S.run();
}

} // namespace texrender
