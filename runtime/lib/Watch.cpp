// texrender --watch: the progressive render loop and the file watcher (Watch.h, docs/live.md).
#include "texrender/Watch.h"

#include "texrender/Error.h"
#include "texrender/Image.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace texrender {

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

namespace {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void say(const std::string &Line) {
  std::fprintf(stderr, "texrender: watch: %s\n", Line.c_str());
  std::fflush(stderr);
}

std::string ms(double Seconds) { return std::to_string(int(Seconds * 1000 + 0.5)) + " ms"; }

/// texcc on the changed graph, on a thread of its own, while the current kernel renders.
struct Regeneration {
  std::thread Thread;
  std::atomic<bool> Done{false};
  std::optional<Layout> Result;
  std::string Log;   // texcc's diagnostics when it failed
  json Graph;
  double Started = 0;
};

class Session {
public:
  Session(WatchOptions Opts, const Layout &Initial) : O(std::move(Opts)), Lay(Initial) {
    O.Renderer.AfterPass = [this](const PassProgress &P) { return afterPass(P); };
    GraphPath = fs::absolute(Lay.GraphPath).string();
    Graph = LayGraph = json::parse(readWholeFile(GraphPath, " graph"));
    TempRoot = (fs::temp_directory_path() / ("texrender-watch-" + std::to_string(::getpid()))).string();
    fs::create_directories(TempRoot);
  }
  ~Session() {
    if (Job && Job->Thread.joinable())
      Job->Thread.join();
    std::error_code EC;
    fs::remove_all(TempRoot, EC);
  }
  unsigned run();

private:
  bool stopping() const { return O.Stop && O.Stop->load(); }
  bool jobDone() const { return Job && Job->Done.load(); }
  bool afterPass(const PassProgress &P);
  void poll();
  void watchFiles();
  void writeProgress(const std::vector<float> &Image);
  void applyChanges();
  /// Changed: the graph's source files that changed (empty: only the graph did).
  void applyGraph(const std::set<std::string> &Changed);
  void applyEdits(const std::vector<std::string> &Lines, const json &New);
  void startJob(const json &New, const std::string &What);
  void adoptJob();
  void reloadScene();

  WatchOptions O;
  Layout Lay;
  std::unique_ptr<Renderer> R;
  std::unique_ptr<LiveEditor> Editor;
  std::string GraphPath, TempRoot;
  json Graph;    // the graph rendered now: LayGraph plus the live edits applied since
  json LayGraph; // the graph Lay was compiled from
  FileWatcher Files;
  std::set<std::string> Changed;
  std::unique_ptr<Regeneration> Job;
  bool JobAgain = false;
  unsigned Generation = 0, Frames = 0;
  // Noticed: when the change being applied was seen; ChangeAt: when the change whose first
  // refined frame is awaited was seen (0: none; set once a change is applied, not on an error).
  double Noticed = 0, ChangeAt = 0, LastWrite = 0, LastPoll = 0;
};

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

/// Writes the image (atomically: writeImage renames a finished file into place) and, for the
/// first image after a change, reports the change-to-refined-frame latency.
void Session::writeProgress(const std::vector<float> &Image) {
  writeImage(O.Output, O.Width, O.Height, Image);
  LastWrite = nowSeconds();
  if (ChangeAt > 0) {
    say("first refined frame " + ms(LastWrite - ChangeAt) + " after the change (tier " +
        (R->activeTier().empty() ? std::string("-") : R->activeTier()) + ")");
    ChangeAt = 0;
  }
}

bool Session::afterPass(const PassProgress &P) {
  double Now = nowSeconds();
  if (Now - LastWrite >= 0.25)
    writeProgress(P.Image());
  if (Now - LastPoll >= 0.1)
    poll();
  return !stopping() && Changed.empty() && !jobDone();
}

unsigned Session::run() {
  R = std::make_unique<Renderer>(O.LoadScene(), Lay, O.Renderer);
  Editor = std::make_unique<LiveEditor>(Lay);
  watchFiles();
  say("watching " + GraphPath + ", its sources and " + O.ScenePath + "; Ctrl-C ends");
  while (!stopping()) {
    FrameStats F;
    std::vector<float> Image = R->render(F);
    if (!F.Interrupted || stopping())
      writeProgress(Image);
    if (!F.Interrupted) {
      ++Frames;
      say("frame " + std::to_string(Frames) + ": " + std::to_string(F.SamplesDone) + " spp in " +
          ms(F.Seconds) + ", tier " + (F.Tier.empty() ? std::string("-") : F.Tier) +
          "; kernel builds so far " + std::to_string(R->cl().foregroundBuilds()));
      while (!stopping() && Changed.empty() && !jobDone()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        poll();
      }
    }
    if (stopping())
      break;
    if (jobDone())
      adoptJob();
    if (!Changed.empty())
      applyChanges();
  }
  return Frames;
}

void Session::applyChanges() {
  std::set<std::string> Now;
  Now.swap(Changed);
  Noticed = nowSeconds();
  std::string Scene = fs::absolute(O.ScenePath).string();
  bool SceneChanged = Now.erase(Scene) > 0;
  bool GraphChanged = Now.erase(GraphPath) > 0;
  if (SceneChanged)
    reloadScene();
  if (GraphChanged || !Now.empty())
    applyGraph(Now);
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
    ChangeAt = Noticed;
    say(O.ScenePath + " reloaded");
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good scene keeps rendering");
  }
}

void Session::applyGraph(const std::set<std::string> &Sources) {
  json New;
  try {
    New = json::parse(readWholeFile(GraphPath, " graph"));
  } catch (const json::parse_error &E) {
    std::fprintf(stderr, "%s: error: %s\n", GraphPath.c_str(), E.what());
    say("the last good graph keeps rendering");
    return;
  } catch (const Error &E) {
    say("error: " + std::string(E.what()) + "; the last good graph keeps rendering");
    return;
  }
  std::optional<std::vector<std::string>> Edits;
  if (Sources.empty())
    Edits = argumentEdits(Graph, New);
  std::string What;
  for (const std::string &S : Sources)
    What += (What.empty() ? "" : ", ") + S;
  if (Edits)
    applyEdits(*Edits, New);
  else
    startJob(New, What.empty() ? GraphPath : What);
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
    return;
  }
  if (std::optional<EditProblem> P = Editor->check(Edits)) {
    std::fprintf(stderr, "%s: error: edit '%s': %s; nothing applied\n", GraphPath.c_str(),
                 Edits[P->Index].Text.c_str(), P->Message.c_str());
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
    return;
  }
  Graph = New;
  ChangeAt = Noticed;
  say("applied '" + Text + "' in " + ms(nowSeconds() - T0) + ", " +
      std::to_string(R->cl().foregroundBuilds() - Builds) + " kernel build(s)");
}

void Session::startJob(const json &New, const std::string &What) {
  if (Job) {
    JobAgain = true; // the newest files are compiled once this run ends
    return;
  }
  Job = std::make_unique<Regeneration>();
  Job->Graph = New;
  Job->Started = Noticed; // its latency is reported once its kernel is adopted
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
    applyGraph({GraphPath}); // files saved while it ran: compile them as they are now
    return;
  }
  if (!J->Result) {
    std::fputs(J->Log.c_str(), stderr);
    if (!J->Log.empty() && J->Log.back() != '\n')
      std::fputc('\n', stderr);
    say("texcc failed: the last good kernel keeps rendering");
    return;
  }
  unsigned Builds = R->cl().foregroundBuilds();
  try {
    R->setLayout(*J->Result);
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good kernel keeps rendering");
    return;
  }
  Lay = *J->Result;
  Editor = std::make_unique<LiveEditor>(Lay);
  Graph = LayGraph = J->Graph;
  watchFiles();
  ChangeAt = J->Started;
  say("new kernel from texcc after " + ms(nowSeconds() - J->Started) + ", " +
      std::to_string(R->cl().foregroundBuilds() - Builds) + " kernel build(s) waited for");
}

} // namespace

unsigned runWatch(WatchOptions O, const Layout &Initial) {
  Session S(std::move(O), Initial);
  return S.run();
}

} // namespace texrender
