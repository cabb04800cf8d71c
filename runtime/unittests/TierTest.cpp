// Tiered texture execution, host side: the --tier policy names, the "wait" edit-script line,
// a shape-mode layout without its interp fallback, and BackgroundBuild's hand-over of a result
// made on another thread. The tiers themselves run in testsuite/runtime/tier-*.test.
#include "texrender/Error.h"
#include "texrender/Layout.h"
#include "texrender/LiveEdit.h"
#include "texrender/TextureTiers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
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
      << R"({"texcc": 1, "mode": "shape", "kernel": {"source": "proctex.cl"}, "materials": []})";
  std::ofstream(Dir / "args.bin") << "";
  try {
    loadLayout(Dir.string());
    FAIL() << "no error";
  } catch (const Error &E) {
    EXPECT_NE(std::string(E.what()).find("/kernel/interpFallback"), std::string::npos) << E.what();
  }
  std::ofstream(Dir / "layout.json")
      << R"({"texcc": 1, "mode": "shape", "kernel": {"source": "proctex.cl",
             "interpFallback": "proctex.interp.cl", "shapes": [{"id": 0, "materials": []}]},
             "materials": []})";
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
