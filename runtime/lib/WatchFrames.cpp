// texrender --watch: the progressive image (WatchSession.h): the pass-time model that sizes the
// reduced first pass, the passes rendered and cut, and the images written (docs/live.md).
#include "WatchSession.h"

#include "texrender/Image.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace texrender {

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

namespace watch {

std::vector<float> Session::renderThen(FrameStats &Stats, const std::function<void()> &Restore) {
  std::vector<float> Image;
  try {
    Image = R->render(Stats);
  } catch (...) {
    Restore();
    throw;
  }
  Restore();
  return Image;
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
    Small = renderThen(Stats, [&] { S = Saved; });
  } catch (const TextureFault &X) {
    return recoverFromFault(X);
  }
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
  std::string Tier = R->tiers().activeTier().empty() ? std::string("-") : R->tiers().activeTier();
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
  if (Source.Adopted > 0) {
    E["source"] = ordered_json{{"latency_ms", eventMs(LastWrite - Source.Noticed)},
                               {"texcc_ms", eventMs(Source.TexccDone - Source.Noticed)},
                               {"to_adopt_ms", eventMs(Source.AdoptStart - Source.TexccDone)},
                               {"adopt_ms", eventMs(Source.Adopted - Source.AdoptStart)},
                               {"build_ms", std::round(Source.BuildMs * 100) / 100},
                               {"builds", Source.Builds},
                               {"prime", Source.Primed},
                               {"to_pass_ms", eventMs(PassStart - Source.Adopted)},
                               {"pass_ms", eventMs(PassEnd - PassStart)},
                               {"write_ms", eventMs(LastWrite - WriteStart)}};
    say("source change: first frame " + ms(LastWrite - Source.Noticed) +
        " after it was noticed: texcc " + ms(Source.TexccDone - Source.Noticed) + ", " +
        Source.Primed + ", adopted " + ms(Source.AdoptStart - Source.TexccDone) + " later in " +
        ms(Source.Adopted - Source.AdoptStart) + " (" + std::to_string(Source.Builds) +
        " kernel build(s) from source, " + std::to_string(int(Source.BuildMs + 0.5)) +
        " ms loading, building and warming up programs; tier " + Tier + "), " +
        (Reduced ? "reduced pass (1/" + std::to_string(Factor) + ") " : std::string("pass ")) +
        ms(PassEnd - PassStart) + " after " + ms(PassStart - Source.Adopted) +
        ", image written in " + ms(LastWrite - WriteStart));
    Source = {};
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
  // $TEXRENDER_HOLD_PASS (tests of the cut, docs/live.md): the second full-resolution pass of
  // the first frame starts whatever came after the first (afterPass) and waits at its first
  // bounce for a change, so that the change finds a pass in flight whatever the machine's speed.
  if (HoldPass && PassesInFrame == 1) {
    HoldPass = false;
    while (!stopping() && !work()) {
      Waker->waitFor(100);
      poll();
    }
  }
  if (nowSeconds() - LastPoll >= 0.1)
    poll();
  return !stopping() && work();
}

bool Session::afterPass(const PassProgress &P) {
  double Now = nowSeconds();
  PassEnd = Now;
  ++PassesInFrame;
  Times.record(double(O.Width) * O.Height, Now - PassResume);
  // The first image after a change is written at once; the others at most 4 times a second.
  if (Now - LastWrite >= 0.25 || ChangeAt > 0 || EditAt > 0)
    writeProgress(P.Image(), P.SamplesDone);
  // Once the first image is out: the priming overlaps the first frame's later passes, so that
  // a save right after that frame does not wait for it.
  primeCompiler();
  fullPassDone();
  if (Now - LastPoll >= 0.1)
    poll();
  PassResume = nowSeconds();
  if (HoldPass && PassesInFrame == 1)
    return !stopping(); // pass 2 starts whatever came: cutPass holds it for a change
  return !stopping() && !work();
}

void Session::fullPassDone() {
  // The shape kernel held behind the quick tier (TierManager::setQuickTier): started with the
  // new kernel, its compile slowed this pass.
  if (R->tiers().fullPassDone())
    say("the shape kernel builds in the background now (the quick tier's first full-resolution "
        "pass is done)");
}

void Session::renderFrame() {
  FrameStats F;
  ++Accumulation;
  if (TierSwitch) {
    TierSwitch = false;
    std::string After;
    if (QuickSince > 0) // adopted by the pass below
      After = " (the shape kernel behind the quick tier, " + ms(nowSeconds() - QuickSince) +
              " after the change that needed it)";
    QuickSince = 0;
    say("the background build is done: accumulation restarts with its kernel" + After);
  }
  PassStart = PassResume = nowSeconds();
  PassesInFrame = 0;
  Cuttable = true;
  std::vector<float> Image;
  try {
    Image = renderThen(F, [this] { Cuttable = false; });
  } catch (const TextureFault &X) {
    return recoverFromFault(X);
  }
  if ((!F.Interrupted || stopping()) && F.SamplesDone > 0)
    writeProgress(Image, F.SamplesDone);
  if (F.SamplesDone > 0)
    fullPassDone();
  if (F.PassCut)
    say("pass " + std::to_string(F.SamplesDone + 1) + " cut short after " +
        ms(nowSeconds() - PassResume) + " for a change (" + std::to_string(++PassesCut) +
        " so far)");
  if (F.Interrupted)
    return;
  Dirty = false;
  ++Frames;
  RenderingGood = false;
  if (!Good || Good->Lay.Dir != Lay.Dir || !texcc::graph::sameGraph(Good->Graph, Editor->graph()))
    Good = GoodState{Lay, Editor->graph()};
  say("frame " + std::to_string(Frames) + ": " + std::to_string(F.SamplesDone) + " spp in " +
      ms(F.Seconds) + ", tier " + (F.Tier.empty() ? std::string("-") : F.Tier) +
      "; kernel builds so far " + std::to_string(R->cl().foregroundBuilds()));
  primeCompiler();
  // The interp fallback of a regenerated shape kernel, held back while its first frames
  // rendered (TierManager::setDeferFallbackBuilds; after the quick tier, until the shape kernel
  // built behind it has taken over).
  if (R->tiers().startDeferredBuild())
    say("the interp fallback builds in the background now (held back until a complete frame)");
  // Shape mode's quick tier: the programs of the layout's functions, built once in the
  // background so that a saved source file rebuilds only the changed function's.
  else if (R->tiers().warmQuickPrograms())
    say("the quick tier's programs build in the background now");
  while (!stopping() && !work())
    idle();
}

void Session::recoverFromFault(const TextureFault &X) {
  // Not the end of the session (docs/live.md: a mistake never stops the preview): the fault is
  // the user's texture code under the state just changed.
  const std::string M = X.what();
  say("error: " + M);
  errorEvent(M);
  EditAt = ChangeAt = QuickSince = 0;
  Source = {};
  const bool Again = RenderingGood;
  RenderingGood = false;
  auto wait = [&](const std::string &Why) {
    say(Why + ": nothing renders until the graph, its sources or the scene change");
    Dirty = false;
  };
  if (!Good)
    return wait("no frame has completed without a fault yet");
  if (Again)
    return wait("the last good state faults too");
  try {
    std::optional<std::vector<texcc::graph::Edit>> Back;
    std::string Why;
    if (Good->Lay.Dir == Lay.Dir) // the same kernel: the edits since, undone
      Back = texcc::graph::diff(Editor->graph(), Good->Graph, Why);
    std::string Kernel;
    if (!Back) { // another kernel (texcc's, a rewiring's): the good one, and its edits
      R->setLayout(Good->Lay);
      Lay = Good->Lay;
      Editor = std::make_unique<LiveEditor>(Lay, Regen);
      Back = texcc::graph::diff(Editor->graph(), Good->Graph, Why);
      Kernel = "kernel and ";
    }
    if (Back && !Back->empty())
      Editor->apply(*Back, *R);
    watchFiles();
    RenderingGood = Dirty = true;
    say("the last good " + Kernel + "graph render again" +
        (Back ? std::string() : " (without the control channel's rewirings made before)"));
    reloadEvent("restore"); // front ends show the values rendered again
  } catch (const std::exception &E) {
    say("error: " + std::string(E.what()));
    errorEvent(E.what());
    wait("the last good state could not be restored");
  }
}

} // namespace watch
} // namespace texrender
