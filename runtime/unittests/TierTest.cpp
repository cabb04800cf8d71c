// Tiered texture execution, host side: the --tier policy names, the "wait" edit-script line,
// a shape-mode layout without its interp fallback, BackgroundBuild's hand-over of a result
// made on another thread, the tier manager's build plan (which tier renders the first
// frame, which one builds in the background) for every policy and program-cache state, and its
// events (built, adopted, failed) and build queue (a deferred fallback) on two tiny kernels. The tiers themselves run in
// testsuite/runtime/tier-*.test.
#include "texrender/Error.h"
#include "texrender/Layout.h"
#include "texrender/LiveEdit.h"
#include "texrender/TextureTiers.h"
#include "texrender/TierManager.h"

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

TEST(Tier, PolicyNames) {
  for (TierPolicy P : {TierPolicy::Auto, TierPolicy::Interp, TierPolicy::Shape})
    EXPECT_EQ(parseTierPolicy(tierPolicyName(P)), P);
  try {
    parseTierPolicy("fast");
    FAIL() << "no error";
  } catch (const Error &E) {
    EXPECT_STREQ(E.what(), "--tier: unknown tier policy 'fast' (expected auto, interp or shape)");
  }
}

TEST(Tier, WaitLine) {
  EXPECT_EQ(parseEdit("wait").K, Edit::Kind::Wait);
  EXPECT_EQ(parseEdit("  wait ").K, Edit::Kind::Wait);
  EXPECT_THROW(parseEdit("wait 2"), Error);
}

TEST(Tier, ShapeLayoutNeedsItsFallback) {
  fs::path Dir = fs::temp_directory_path() / ("texrender-tier-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  std::ofstream(Dir / "layout.json")
      << R"({"texcc": 1, "mode": "shape", "kernel": {"source": "proctex.cl"}, "materials": [],
             "capabilities": {"shapeKeyed": true, "interpFallback": true}})";
  std::ofstream(Dir / "args.bin") << "";
  try {
    loadLayout(Dir.string());
    FAIL() << "no error";
  } catch (const Error &E) {
    EXPECT_NE(std::string(E.what()).find("interpFallback"), std::string::npos) << E.what();
  }
  std::ofstream(Dir / "layout.json")
      << R"({"texcc": 1, "mode": "shape", "kernel": {"source": "proctex.cl",
             "interpFallback": "proctex.interp.cl", "shapes": [{"id": 0, "materials": []}]},
             "materials": [], "capabilities": {"shapeKeyed": true, "interpFallback": true}})";
  Layout L = loadLayout(Dir.string());
  EXPECT_EQ(L.InterpFallback, (Dir / "proctex.interp.cl").string());
  EXPECT_EQ(L.NumShapes, 1u);
  fs::remove_all(Dir);
}

TEST(Tier, BackgroundBuildHandsOverItsResult) {
  std::atomic<bool> Go{false};
  std::thread::id Main = std::this_thread::get_id();
  bool OtherThread = false;
  BackgroundBuild B(
      [&] {
        while (!Go)
          std::this_thread::yield();
        OtherThread = std::this_thread::get_id() != Main;
        TierBuildResult R;
        R.L.Mode = "shape";
        R.Error = "none";
        return R;
      },
      7);
  EXPECT_FALSE(B.ready());
  Go = true;
  B.wait();
  EXPECT_TRUE(B.ready());
  EXPECT_EQ(B.eventIndex(), 7u);
  TierBuildResult R = B.take();
  EXPECT_TRUE(OtherThread);
  EXPECT_EQ(R.L.Mode, "shape");
  EXPECT_EQ(R.Error, "none");
}

// A background build's thread runs the nice increment asked for above the thread that starts it,
// capped at 19: DefaultBackgroundBuildNice (0: the renderer's own priority; at an absolute 19, the
// old default, a continuous nice-0 load elsewhere on the machine starved it) unless
// $TEXRENDER_BUILD_NICE says otherwise.
TEST(Tier, BackgroundBuildRunsAtItsNiceValue) {
  auto NiceOf = [](std::optional<int> Nice) {
    int Seen = -100;
    auto Job = [&] {
      Seen = getpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)));
      return TierBuildResult();
    };
    std::unique_ptr<BackgroundBuild> B =
        Nice ? std::make_unique<BackgroundBuild>(Job, 0, *Nice)
             : std::make_unique<BackgroundBuild>(Job, 0);
    B->wait();
    B->take();
    return Seen;
  };
  const int Own = getpriority(PRIO_PROCESS, 0);
  if (std::getenv("TEXRENDER_BUILD_NICE"))
    GTEST_SKIP() << "$TEXRENDER_BUILD_NICE sets another increment";
  EXPECT_EQ(NiceOf(std::nullopt), Own);
  EXPECT_EQ(NiceOf(19), 19);
  EXPECT_EQ(NiceOf(0), Own);
  EXPECT_EQ(NiceOf(3), std::min(19, Own + 3));
}

// Background compiles wait for a pause in interactive edits (PoCL holds up every launch while
// it compiles): waitForEditPause returns EditPauseSeconds after the last noteInteractiveEdit,
// not before, and at once when that is past.
TEST(Tier, BackgroundCompilesWaitForAPauseInEdits) {
  noteInteractiveEdit();
  const double T0 = steadySeconds();
  std::thread Editor([] {
    for (int I = 0; I < 3; ++I) { // a slider dragged: an edit every 0.1 s for 0.3 s
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      noteInteractiveEdit();
    }
  });
  waitForEditPause();
  const double Waited = steadySeconds() - T0;
  Editor.join();
  EXPECT_GE(Waited, 0.3 + EditPauseSeconds - 0.01);
  const double T1 = steadySeconds();
  waitForEditPause();
  EXPECT_LT(steadySeconds() - T1, 0.05);
}

// planTierBuilds, every (policy, shape cached, fallback cached): what is built before the
// first frame, what on the background thread. The first frame renders with the shape kernel
// when it is built now.
TEST(Tier, BuildPlanOfEveryPolicyAndCacheState) {
  struct Row {
    TierPolicy P;
    bool ShapeCached, FallbackCached;
    bool ShapeNow, InterpNow, ShapeLater, InterpLater;
  };
  const TierPolicy Auto = TierPolicy::Auto, Interp = TierPolicy::Interp,
                   Shape = TierPolicy::Shape;
  const Row Rows[] = {
      // auto: nothing cached builds the shape kernel now, the fallback behind it.
      {Auto, false, false, true, false, false, true},
      // auto: a cached program is a load: the shape kernel loads, the fallback builds later.
      {Auto, true, false, true, false, false, true},
      // auto: only the fallback cached: it renders at once, the shape kernel builds later.
      {Auto, false, true, false, true, true, false},
      // auto: both cached: both load now, nothing in the background.
      {Auto, true, true, true, true, false, false},
      // interp and shape: their own program now, whatever the cache holds; nothing later.
      {Interp, false, false, false, true, false, false},
      {Interp, true, false, false, true, false, false},
      {Interp, false, true, false, true, false, false},
      {Interp, true, true, false, true, false, false},
      {Shape, false, false, true, false, false, false},
      {Shape, true, false, true, false, false, false},
      {Shape, false, true, true, false, false, false},
      {Shape, true, true, true, false, false, false},
  };
  for (const Row &R : Rows) {
    SCOPED_TRACE(std::string(tierPolicyName(R.P)) + " shapeCached=" +
                 std::to_string(R.ShapeCached) + " fallbackCached=" +
                 std::to_string(R.FallbackCached));
    TierBuildPlan Plan = planTierBuilds(R.P, R.ShapeCached, R.FallbackCached);
    const ProgramRole Primary = ProgramRole::Primary, Fallback = ProgramRole::Fallback;
    EXPECT_EQ(Plan.now(Primary), R.ShapeNow);
    EXPECT_EQ(Plan.now(Fallback), R.InterpNow);
    EXPECT_EQ(Plan.later(Primary), R.ShapeLater);
    EXPECT_EQ(Plan.later(Fallback), R.InterpLater);
    // Something renders the first frame, and nothing is built twice.
    EXPECT_TRUE(Plan.now(Primary) || Plan.now(Fallback));
    EXPECT_FALSE(Plan.now(Primary) && Plan.later(Primary));
    EXPECT_FALSE(Plan.now(Fallback) && Plan.later(Fallback));
  }
}

// The tier manager's events (TierEvent), on a shape-mode layout of two tiny kernels: a
// background build is Built when it ends (nothing adopted yet, the getters unchanged), then
// Adopted at a boundary (collect at rest for a fallback built alone, the next frame for a new
// primary); a failed build is Failed with its error. No waiting on the clock: the manager's
// wake-up (setWake) says when a build has ended.
namespace {

/// A kernel with the texture kernels' 9 arguments (numHits third) that writes nothing.
const char *TinyKernel = "kernel void texcc_proctex(global float *a, global float *b, int n,\n"
                         "    global float *c, global float *d, global float *e,\n"
                         "    global float *f, global float *g, global float *h) {\n"
                         "  if ((int)get_global_id(0) < n) a[0] = 1.0f;\n}\n";

/// A shape-mode folder: proctex.cl and its interp fallback (FallbackBroken: one that does not
/// compile, though it declares the kernel).
Layout tinyShapeLayout(const fs::path &Dir, bool FallbackBroken) {
  fs::create_directories(Dir);
  std::ofstream(Dir / "layout.json")
      << R"({"texcc": 1, "mode": "shape", "kernel": {"source": "proctex.cl",
             "interpFallback": "proctex.interp.cl", "shapes": []}, "materials": [],
             "stackSlots": 2, "capabilities": {"shapeKeyed": true, "interpFallback": true}})";
  std::ofstream(Dir / "args.bin") << "";
  std::ofstream(Dir / "proctex.cl") << "// shape\n" << TinyKernel;
  std::ofstream(Dir / "proctex.interp.cl")
      << "// interp\n" << TinyKernel << (FallbackBroken ? "this is not OpenCL C;\n" : "");
  return loadLayout(Dir.string());
}

/// The events a manager sends, and a wait for its build threads' wake-ups.
struct EventLog {
  std::vector<TierEvent> Seen;
  std::mutex M;
  std::condition_variable Cv;
  unsigned Wakes = 0;
  void wake() {
    std::lock_guard<std::mutex> L(M);
    ++Wakes;
    Cv.notify_all();
  }
  void waitForWakes(unsigned N) {
    std::unique_lock<std::mutex> L(M);
    Cv.wait(L, [&] { return Wakes >= N; });
  }
  /// "built fallback bg" ... per background event, in order.
  std::vector<std::string> background() const {
    std::vector<std::string> Out;
    for (const TierEvent &E : Seen)
      if (E.Background)
        Out.push_back(std::string(tierEventName(E.K)) + " " +
                      texcc::kernel::programRoleName(E.Role) + (E.Switches ? " switches" : ""));
    return Out;
  }
};

struct TierFixture {
  fs::path Dir;
  Layout Lay;
  std::unique_ptr<ClContext> Cl;
  std::unique_ptr<TierManager> T;
  EventLog Log;
  TierFixture(const std::string &Name, bool FallbackBroken) {
    Dir = fs::temp_directory_path() /
          ("texrender-tier-events-" + Name + "-" + std::to_string(::getpid()));
    fs::remove_all(Dir);
    Lay = tinyShapeLayout(Dir / "out", FallbackBroken);
    Cl = std::make_unique<ClContext>(0, (Dir / "cache").string()); // nothing cached
    T = std::make_unique<TierManager>(*Cl, Lay, TierPolicy::Auto, false, "", steadySeconds(),
                                      [this](Layout &&L) {
                                        Lay = std::move(L);
                                        return true;
                                      });
    T->subscribe([this](const TierEvent &E) { Log.Seen.push_back(E); });
    T->setWake([this] { Log.wake(); });
  }
  ~TierFixture() {
    T.reset();
    fs::remove_all(Dir);
  }
};

} // namespace

TEST(TierEvents, FallbackBuiltThenAdoptedAtRest) {
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  TierFixture F("adopt", /*FallbackBroken=*/false);
  F.T->build(true); // nothing cached: the shape kernel now, its fallback in the background
  ASSERT_EQ(F.T->activeTier(), "shape");
  ASSERT_EQ(F.Log.Seen.size(), 1u);
  EXPECT_EQ(F.Log.Seen[0].K, TierEvent::Kind::Built);
  EXPECT_EQ(F.Log.Seen[0].Role, ProgramRole::Primary);
  EXPECT_FALSE(F.Log.Seen[0].Background);
  F.Log.waitForWakes(1);
  EXPECT_FALSE(F.T->canSwitchShapes()); // ended, but nobody has looked: no side effect
  EXPECT_FALSE(F.T->switchPending());   // a fallback built alone switches nothing
  F.T->collect(/*Rest=*/false);         // within a pass: told, not adopted
  EXPECT_EQ(F.Log.background(), std::vector<std::string>{"built fallback"});
  EXPECT_EQ(F.T->fallbackStackSlots(), 0u);
  EXPECT_FALSE(F.T->canSwitchShapes());
  F.T->collect(/*Rest=*/false); // once
  EXPECT_EQ(F.Log.background().size(), 1u);
  F.T->collect(/*Rest=*/true); // between frames: adopted
  EXPECT_EQ(F.Log.background(), (std::vector<std::string>{"built fallback", "adopted fallback"}));
  EXPECT_TRUE(F.T->canSwitchShapes());
  EXPECT_GE(F.T->fallbackStackSlots(), 2u);
  const TierEvent &A = F.Log.Seen.back();
  EXPECT_EQ(A.Reason, "initial");
  EXPECT_GT(A.Seconds, 0.0);
  EXPECT_EQ(F.T->activeTier(), "shape"); // the shape kernel renders on

  // A new shape: the fallback renders at once, the new layout's programs build behind it and
  // are adopted by the next frame, not before.
  F.T->switchShapes(true, [L = F.Lay] { return L; }, [](Layout &) {});
  EXPECT_EQ(F.T->activeTier(), "interp");
  EXPECT_TRUE(F.T->switchPending());
  F.Log.waitForWakes(2);
  F.T->collect(/*Rest=*/true);
  EXPECT_EQ(F.Log.background(),
            (std::vector<std::string>{"built fallback", "adopted fallback",
                                      "built primary switches", "built fallback switches"}));
  EXPECT_FALSE(F.T->switchPending());
  EXPECT_EQ(F.T->activeTier(), "interp"); // adoption is the frame's
  EXPECT_EQ(F.T->beginFrame(), "shape");
  EXPECT_EQ(F.Log.background(),
            (std::vector<std::string>{"built fallback", "adopted fallback",
                                      "built primary switches", "built fallback switches",
                                      "adopted primary switches", "adopted fallback switches"}));
  EXPECT_EQ(F.Log.Seen.back().Reason, "shape change");
}

TEST(TierEvents, FailedBuildSaysWhy) {
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  TierFixture F("fail", /*FallbackBroken=*/true);
  F.T->build(true);
  F.Log.waitForWakes(1);
  F.T->collect(/*Rest=*/true);
  ASSERT_EQ(F.Log.background(), std::vector<std::string>{"failed fallback"});
  const TierEvent &E = F.Log.Seen.back();
  EXPECT_EQ(E.Reason, "initial");
  EXPECT_FALSE(E.Error.empty());
  EXPECT_FALSE(F.T->canSwitchShapes());
  EXPECT_EQ(F.T->activeTier(), "shape");
  EXPECT_EQ(F.T->beginFrame(), "shape"); // nothing more to adopt
  EXPECT_EQ(F.Log.background().size(), 1u);
  EXPECT_EQ(F.T->buildEvents().back().Error, E.Error);
}

// The build queue: a fallback built alone (setDeferFallbackBuilds) waits for startDeferredBuild,
// not for the layout: nothing starts with it, and nothing is pending to switch to. Released, it
// starts once (a second call finds nothing), is Built when it ends and Adopted at rest.
TEST(TierEvents, DeferredFallbackWaitsForItsRelease) {
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  TierFixture F("defer", /*FallbackBroken=*/false);
  F.T->setDeferFallbackBuilds(true);
  F.T->build(true); // nothing cached: the shape kernel now, its fallback held back
  ASSERT_EQ(F.T->activeTier(), "shape");
  EXPECT_FALSE(F.T->switchPending());
  F.T->collect(/*Rest=*/true);
  EXPECT_EQ(F.T->beginFrame(), "shape");
  ASSERT_EQ(F.T->buildEvents().size(), 1u); // the foreground build only: nothing started
  EXPECT_TRUE(F.Log.background().empty());
  EXPECT_TRUE(F.T->startDeferredBuild());
  EXPECT_FALSE(F.T->startDeferredBuild()); // started: nothing left to start
  EXPECT_FALSE(F.T->switchPending());
  ASSERT_EQ(F.T->buildEvents().size(), 2u);
  EXPECT_EQ(F.T->buildEvents().back().Kernel, "interp");
  EXPECT_TRUE(F.T->buildEvents().back().Background);
  F.Log.waitForWakes(1);
  F.T->collect(/*Rest=*/true);
  EXPECT_EQ(F.Log.background(), (std::vector<std::string>{"built fallback", "adopted fallback"}));
  EXPECT_TRUE(F.T->canSwitchShapes());
  EXPECT_EQ(F.T->activeTier(), "shape");
}
