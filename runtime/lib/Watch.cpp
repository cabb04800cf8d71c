// texrender --watch: the session (WatchSession.h): the files watched, the control channel's
// commands, the changes applied and texcc run in the background (Watch.h, docs/live.md).
#include "texrender/Watch.h"

#include "WatchSession.h"

#include "texrender/Error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texrender {
namespace watch {

void Session::event(const ordered_json &E) {
  if (!O.Control)
    return;
  std::string Line = E.dump(-1, ' ', false, json::error_handler_t::replace);
  Line += '\n';
  std::fwrite(Line.data(), 1, Line.size(), stdout);
  std::fflush(stdout);
}

void Session::reloadEvent(const std::string &What) {
  event({{"event", "reload"}, {"what", What}, {"schema", editSchema(Lay, Editor->graph())}});
}

void Session::errorEvent(const std::string &Message, std::optional<long long> Id) {
  ordered_json E{{"event", "error"}};
  if (Id)
    E["id"] = *Id;
  std::string M = Message;
  while (!M.empty() && M.back() == '\n')
    M.pop_back();
  E["message"] = texcc::boundedMessage(M);
  event(E);
}

void Session::watchFiles() {
  std::vector<std::string> Paths = graphFiles(GraphPath, Editor->graph().Sources);
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
  // A control line or texcc's end wakes it at once (Waker), a saved file at the next poll.
  Waker->waitFor(std::max(1, int((End - nowSeconds()) * 1000)));
  // Between frames: an interp fallback built alone is adopted now, not at the next frame (a
  // rewiring to a new shape needs it); onTierEvent hears of it.
  R->tiers().collect(/*Rest=*/true);
  if (nowSeconds() - LastPoll >= 0.1)
    poll();
}

bool Session::tierBuilt() {
  R->tiers().collect(/*Rest=*/false); // maybe within a pass: adopts nothing
  return TierSwitch;
}

void Session::followTiers(Renderer &Into) {
  TierManager &T = Into.tiers();
  T.subscribe([this](const TierEvent &E) { onTierEvent(E); });
  T.setWake([W = Waker] { W->notify(); });
  T.setDeferFallbackBuilds(true); // started after a complete frame (renderFrame)
  T.setQuickTier(true);           // its programs warmed up after a complete frame
}

void Session::onTierEvent(const TierEvent &E) {
  if (!E.Background)
    return;
  if (E.Switches && E.K != TierEvent::Kind::Adopted)
    TierSwitch = true;
  if (E.K == TierEvent::Kind::Built && E.Role == ProgramRole::Quick)
    say("the quick tier's programs are built (" + std::to_string(E.Programs) + " in " +
        ms(E.Seconds) + ")");
  if (E.K == TierEvent::Kind::Adopted && E.Role == ProgramRole::Fallback && !E.Switches)
    say("the interp fallback is built (" + ms(E.Seconds) + "); a rewiring to a new shape "
        "renders with it at once");
}

WatchResult Session::run() {
  R = std::make_unique<Renderer>(O.LoadScene(), Lay, O.Renderer);
  followTiers(*R);
  Editor = std::make_unique<LiveEditor>(Lay, Regen);
  watchFiles();
  say("watching " + GraphPath + ", its sources and " + O.ScenePath + "; Ctrl-C ends");
  if (O.Control) {
    ordered_json Sources = json::array();
    for (const std::string &S : graphFiles(GraphPath, Editor->graph().Sources))
      if (S != GraphPath)
        Sources.push_back(S);
    event({{"event", "ready"}, {"graph", GraphPath}, {"sources", Sources},
           {"width", O.Width}, {"height", O.Height}, {"schema", editSchema(Lay, Editor->graph())}});
    Input = std::make_unique<ControlInput>(Waker);
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

void Session::noteQuickTier(double Since) {
  QuickSince = 0;
  if (R->tiers().activeTier() != QuickTierName || !R->tiers().switchPending())
    return;
  QuickSince = Since;
  say("the shape kernel builds in the background after the quick tier's first full-resolution "
      "pass; the quick tier renders until it is ready");
}

void Session::primeCompiler() {
  if (Primed)
    return;
  Primed = true;
  // A text PoCL's kernel cache (keyed on the preprocessed source) has not seen: it compiles.
  const unsigned long long Salt =
      (unsigned long long)std::chrono::steady_clock::now().time_since_epoch().count() ^
      ((unsigned long long)::getpid() << 32);
  const std::string Source = "kernel void texrender_watch_prime(global uint *out) { out[0] = " +
                             std::to_string(unsigned(Salt % 4294967291ULL)) + "u; }\n";
  const double Start = nowSeconds();
  // Nothing is printed here: a line from this thread would land anywhere in stderr's sequence.
  Prime = std::thread([Ctx = R->cl().context(), Device = R->cl().device(), Source, Start,
                       Took = &PrimeSeconds] {
    try {
      cl::Program P(Ctx, Source);
      P.build({Device}, "-cl-std=CL1.2");
    } catch (const std::exception &) {
      // Only a head start for the first saved source file: nothing depends on it.
    }
    *Took = nowSeconds() - Start;
  });
}

std::string Session::waitForPrime() {
  if (!Primed)
    return "the compiler not primed";
  const double Start = nowSeconds();
  if (Prime.joinable())
    Prime.join();
  return "the compiler primed in " + ms(PrimeSeconds) + ", waited " + ms(nowSeconds() - Start) +
         " for it";
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
  unsigned Builds = R->cl().foregroundBuilds();
  double T0 = nowSeconds();
  texcc::graph::Edit Typed;
  try {
    Typed = graphEdit(Ed);
    noteInteractiveEdit(); // background compiles wait for a pause (TextureTiers.h)
    Editor->apply(Typed, *R, Ed.Text); // validated once: a refusal changes nothing
  } catch (const Error &X) {
    return refuse(X.what());
  }
  double Took = nowSeconds() - T0;
  unsigned Built = R->cl().foregroundBuilds() - Builds;
  LastEdit = Id;
  Dirty = true;
  EditAt = C.ReadAt;
  AppliedAt = nowSeconds();
  say("applied '" + Ed.Text + "' (id " + std::to_string(*Id) + ") in " + ms(Took) + ", " +
      std::to_string(Built) + " kernel build(s)");
  // What changed, as texrender parsed the line (a front end never splits NODE.ARG itself:
  // node ids may hold dots).
  ordered_json Applied{{"event", "applied"}, {"id", *Id}, {"ms", eventMs(Took)},
                       {"builds", Built}, {"node", Ed.Node}, {"arg", Ed.Arg}};
  if (Ed.K == Edit::Kind::Rewire)
    Applied["source"] = Ed.Value;
  else
    Applied["value"] = texcc::graph::argumentJson(Typed.Value);
  Applied["input"] = inputSchema(Lay, Editor->graph(), Ed.Node, Ed.Arg);
  event(Applied);
  if (Built > 0) // a rewiring regenerated the kernel
    noteQuickTier(C.ReadAt);
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

void Session::applyKeptEdits(const texcc::graph::Graph &Edited) {
  std::string Why;
  std::optional<std::vector<texcc::graph::Edit>> Edits = texcc::graph::diff(Editor->graph(), Edited, Why);
  if (!Edits)
    return;
  for (const texcc::graph::Edit &E : *Edits) {
    try {
      Editor->apply(E, *R);
    } catch (const Error &X) {
      say("error: " + std::string(X.what()) + "; this edit is dropped");
      errorEvent(std::string(X.what()) + "; this edit is dropped");
    }
  }
}

void Session::reloadScene() {
  try {
    // The scene changed, not the graph or its kernel: the new renderer starts from the kernel
    // and arguments the live editor renders now, and the editor carries on (nothing validated,
    // encoded or regenerated again). Where the editor's graph is not what is rendered (a shape
    // switch in flight, an edit that failed half-way), it starts from Lay and a new editor
    // applies the edits made since again.
    std::optional<Layout> Carried = Editor->renderedLayout();
    auto New = std::make_unique<Renderer>(O.LoadScene(), Carried ? *Carried : Lay, O.Renderer);
    followTiers(*New);
    // A new OpenCL context: primed again after its first complete frame.
    if (Prime.joinable())
      Prime.join();
    Primed = false;
    std::unique_ptr<LiveEditor> NewEditor;
    if (!Carried) {
      NewEditor = std::make_unique<LiveEditor>(Lay, Regen);
      std::string Why;
      if (auto Edits = texcc::graph::diff(NewEditor->graph(), Editor->graph(), Why))
        NewEditor->apply(*Edits, *New);
    }
    R = std::move(New);
    if (NewEditor)
      Editor = std::move(NewEditor);
    Dirty = true;
    ChangeAt = Noticed;
    say(O.ScenePath + " reloaded");
    reloadEvent("scene");
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good scene keeps rendering");
    errorEvent(std::string(E.what()));
  }
}

void Session::applyGraph(const std::set<std::string> &Sources) {
  std::string Text;
  std::optional<texcc::graph::Graph> New;
  texcc::graph::DiagnosticSink Diags;
  try {
    Text = readGraphFile(GraphPath);
    New = texcc::graph::parseGraph(GraphPath, Text, Diags);
  } catch (const Error &E) {
    say("error: " + std::string(E.what()) + "; the last good graph keeps rendering");
    errorEvent(E.what());
    return;
  }
  if (!New) {
    std::ostringstream Printed;
    Diags.print(Printed);
    std::fputs(Printed.str().c_str(), stderr);
    say("the last good graph keeps rendering");
    errorEvent(Printed.str());
    return;
  }
  const size_t Digest = fileDigest(Text);
  const bool GraphSame = Digest == FileDigest;
  FileDigest = Digest;
  // A saved graph.json is parsed, compared with the graph rendered and applied as edits where
  // only node arguments changed; anything else (and a saved source file) goes to texcc.
  Editor->markCommandLineBakes(*New);
  std::string Why;
  std::optional<std::vector<texcc::graph::Edit>> Edits;
  if (Sources.empty())
    Edits = texcc::graph::diff(Editor->graph(), *New, Why);
  std::string What;
  for (const std::string &S : Sources)
    What += (What.empty() ? "" : ", ") + S;
  if (Edits)
    applyEdits(*Edits);
  else
    startJob(What.empty() ? GraphPath + " (" + Why + ")" : What, GraphSame && !Sources.empty());
}

void Session::applyEdits(const std::vector<texcc::graph::Edit> &Edits) {
  if (Edits.empty()) {
    say(GraphPath + ": saved without a change to apply");
    reloadEvent("graph");
    return;
  }
  unsigned Builds = R->cl().foregroundBuilds();
  double T0 = nowSeconds();
  noteInteractiveEdit();
  try {
    Editor->apply(Edits, *R); // all or nothing
  } catch (const Error &E) {
    std::string M = GraphPath + ": error: " + E.what() + "; nothing applied";
    std::fprintf(stderr, "%s\n", M.c_str());
    errorEvent(M);
    return;
  }
  std::string Text;
  for (const texcc::graph::Edit &E : Edits)
    Text += (Text.empty() ? "" : "; ") + texcc::graph::editText(E);
  Dirty = true;
  ChangeAt = Noticed;
  const unsigned Built = R->cl().foregroundBuilds() - Builds;
  say("applied '" + Text + "' in " + ms(nowSeconds() - T0) + ", " + std::to_string(Built) +
      " kernel build(s)");
  reloadEvent("graph");
  if (Built > 0) // a rewiring regenerated the kernel
    noteQuickTier(Noticed);
}

void Session::startJob(const std::string &What, bool KeepEdits) {
  if (Job) {
    JobAgain = true; // the newest files are compiled once this run ends
    Job->KeepEdits = Job->KeepEdits && KeepEdits;
    return;
  }
  Job = std::make_unique<SourceJob>();
  Job->FileDigest = FileDigest;
  Job->Started = Noticed; // its latency is reported once its kernel is adopted
  Job->KeepEdits = KeepEdits;
  Job->Run = Regen->ofFile(GraphPath, Lay.CompileOptions);
  Folders.push_back(Job->Run->folder());
  say(What + " changed: texcc runs in the background; the current kernel keeps rendering");
  Job->Run->start([W = Waker] { W->notify(); }); // adopted at once, not at the next poll
}

void Session::adoptJob() {
  std::unique_ptr<SourceJob> J = std::move(Job);
  std::optional<Layout> Made = J->Run->takeResult();
  if (JobAgain) {
    JobAgain = false;
    Noticed = J->Started;
    bool Keep = J->KeepEdits;
    applyGraph({GraphPath}); // files saved while it ran: compile them as they are now
    if (Job)
      Job->KeepEdits = Keep && FileDigest == J->FileDigest;
    return;
  }
  if (!Made) {
    const std::string &Log = J->Run->failure();
    std::fputs(Log.c_str(), stderr);
    if (!Log.empty() && Log.back() != '\n')
      std::fputc('\n', stderr);
    say("texcc failed: the last good kernel keeps rendering");
    errorEvent(Log);
    Dirty = true; // a new accumulation of the last good state shows that it is still there
    return;
  }
  const std::string PrimeAccount = waitForPrime();
  unsigned Builds = R->cl().foregroundBuilds();
  const size_t EventsBefore = R->tiers().buildEvents().size();
  const double AdoptStart = nowSeconds();
  try {
    R->setLayout(*Made);
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()) + "; the last good kernel keeps rendering");
    errorEvent(E.what());
    return;
  }
  auto Old = std::make_unique<LiveEditor>(*Made, Regen);
  Lay = *Made;
  std::swap(Editor, Old); // the old editor's graph has the edits to keep
  if (J->KeepEdits)
    applyKeptEdits(Old->graph());
  Old.reset();
  watchFiles();
  Dirty = true;
  ChangeAt = J->Started;
  Source = {J->Started, J->Run->endedAt(), AdoptStart, nowSeconds(), 0,
            R->cl().foregroundBuilds() - Builds, PrimeAccount};
  const std::vector<BuildEvent> &Events = R->tiers().buildEvents();
  for (size_t I = EventsBefore; I < Events.size(); ++I)
    if (!Events[I].Background && Events[I].ReadySeconds >= 0)
      Source.BuildMs += (Events[I].ReadySeconds - Events[I].StartSeconds) * 1000;
  say("new kernel from texcc after " + ms(nowSeconds() - J->Started) + ", " +
      std::to_string(Source.Builds) + " kernel build(s) waited for");
  noteQuickTier(J->Started);
  reloadEvent(J->KeepEdits ? "source" : "graph");
}

} // namespace watch

WatchResult runWatch(WatchOptions O, const Layout &Initial) {
  watch::Session S(std::move(O), Initial);
  return S.run();
}

} // namespace texrender
