// Tiered texture execution, host side: the --tier policy names, the "wait" edit-script line,
// a shape-mode layout without its interp fallback, BackgroundBuild's hand-over of a result
// made on another thread, and the tier manager's build plan (which tier renders the first
// frame, which one builds in the background) for every policy and program-cache state. The tiers themselves run in testsuite/runtime/tier-*.test.
#include "texrender/Error.h"
#include "texrender/Layout.h"
#include "texrender/LiveEdit.h"
#include "texrender/TextureTiers.h"
#include "texrender/TierManager.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
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
    EXPECT_EQ(Plan.ShapeNow, R.ShapeNow);
    EXPECT_EQ(Plan.InterpNow, R.InterpNow);
    EXPECT_EQ(Plan.ShapeLater, R.ShapeLater);
    EXPECT_EQ(Plan.InterpLater, R.InterpLater);
    // Something renders the first frame, and nothing is built twice.
    EXPECT_TRUE(Plan.ShapeNow || Plan.InterpNow);
    EXPECT_FALSE(Plan.ShapeNow && Plan.ShapeLater);
    EXPECT_FALSE(Plan.InterpNow && Plan.InterpLater);
  }
}
