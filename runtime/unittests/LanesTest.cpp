// A frame in lanes (Lanes.h) against the whole frame on one Renderer, on a floor and a cube
// under the cornell layout (skipped without an OpenCL device that splits into two lanes): the
// same image and variance bytes with two and three lanes and a region; and a frame stopped by
// AfterPass ends every lane at the same sample count, equal bit for bit to a render of that many
// samples.
#include "texrender/Error.h"
#include "texrender/Lanes.h"
#include "texrender/Layout.h"
#include "texrender/Renderer.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

using namespace texrender;
using namespace texrender::test;

namespace {

/// makeScene's floor and cube at Width x Height, Spp samples, paths of up to 4 segments.
TestScene floorAndCube(int Width, int Height, int Spp) {
  TestScene T = makeScene(tempDir("lanes"), {FloorAndCube}, Width);
  T.S.Render.Width = Width, T.S.Render.Height = Height, T.S.Render.Spp = Spp;
  T.S.Render.MaxDepth = 4;
  return T;
}

/// testOptions without the quick first build: a lane loads what the frame's Renderer built.
RendererOptions laneOptions() {
  RendererOptions O = testOptions();
  O.QuickFirstBuild = false;
  return O;
}

/// Lanes the default device splits into (0 without a device).
unsigned laneCapacity() {
  if (!haveDevice())
    return 0;
  ClContext Cl(0, "");
  return Cl.laneCapacity();
}

} // namespace

TEST(Lanes, SameImageAsTheWholeFrame) {
  const unsigned Capacity = laneCapacity();
  if (Capacity < 2)
    GTEST_SKIP() << "no OpenCL device that splits into two lanes";
  for (unsigned Lanes = 2; Lanes <= std::min(3u, Capacity); ++Lanes)
    for (bool Region : {false, true}) {
      SCOPED_TRACE("lanes " + std::to_string(Lanes) + (Region ? ", region" : ""));
      TestScene T = floorAndCube(23, 17, 3);
      if (Region)
        T.S.Render.RegionX = 4, T.S.Render.RegionY = 3, T.S.Render.RegionWidth = 11,
        T.S.Render.RegionHeight = 9;
      RendererOptions O = laneOptions();
      Renderer R(T.S, T.L, O);
      ASSERT_EQ(lanesUnavailable(R, O, Lanes), "");
      FrameStats Whole, InLanes;
      std::vector<float> WholeVar, LanesVar;
      std::vector<float> A = R.render(Whole, &WholeVar);
      LaneReport Report;
      std::vector<float> B = renderInLanes(R, T.S, T.L, O, Lanes, InLanes, &LanesVar, &Report);
      EXPECT_EQ(A, B);
      EXPECT_EQ(WholeVar, LanesVar);
      EXPECT_EQ(InLanes.SamplesDone, 3);
      EXPECT_EQ(InLanes.PrimaryRays, Whole.PrimaryRays);
      EXPECT_EQ(Report.Lanes, Lanes);
      EXPECT_GT(Report.MemoryBytes, 0u);
    }
}

TEST(Lanes, StoppedLanesEndAtTheSameSamples) {
  if (laneCapacity() < 2)
    GTEST_SKIP() << "no OpenCL device that splits into two lanes";
  const int W = 20, H = 14;
  TestScene T = floorAndCube(W, H, 64);
  RendererOptions O = laneOptions();
  O.MaxPathsPerPass = size_t(W) * H; // one or two samples per pixel a pass
  int Calls = 0;
  O.AfterPass = [&](const PassProgress &P) {
    EXPECT_GE(P.SamplesDone, 1);
    EXPECT_EQ(P.Spp, 64);
    return ++Calls < 3; // stop at the third pass boundary any lane reaches
  };
  Renderer R(T.S, T.L, O);
  ASSERT_EQ(lanesUnavailable(R, O, 2), "");
  FrameStats Stopped;
  std::vector<float> Image = renderInLanes(R, T.S, T.L, O, 2, Stopped, nullptr);
  EXPECT_TRUE(Stopped.Interrupted);
  EXPECT_GE(Stopped.SamplesDone, 2);
  EXPECT_LT(Stopped.SamplesDone, 64);
  ASSERT_GT(Stopped.Passes, 0u);
  EXPECT_EQ(Stopped.SamplesDone % int(Stopped.Passes), 0); // passes of equal samples
  // The image is that of a render asked for that many samples, on one renderer.
  T.S.Render.Spp = Stopped.SamplesDone;
  RendererOptions Plain = laneOptions();
  Plain.MaxPathsPerPass = O.MaxPathsPerPass;
  Renderer Whole(T.S, T.L, Plain);
  FrameStats WholeStats;
  EXPECT_EQ(Whole.render(WholeStats), Image);
}

TEST(Lanes, UnavailableSaysWhy) {
  if (laneCapacity() < 2)
    GTEST_SKIP() << "no OpenCL device that splits into two lanes";
  TestScene T = floorAndCube(8, 3, 1);
  RendererOptions O = laneOptions();
  Renderer R(T.S, T.L, O);
  EXPECT_EQ(lanesUnavailable(R, O, 1), "one render thread");
  if (laneCapacity() >= 4)
    EXPECT_EQ(lanesUnavailable(R, O, 4), "fewer rows than lanes"); // 3 rows
  else
    EXPECT_EQ(lanesUnavailable(R, O, 4).rfind("the OpenCL device splits into", 0), 0u);
  RendererOptions NoCache = O;
  NoCache.CacheDir = "";
  EXPECT_EQ(lanesUnavailable(R, NoCache, 2).rfind("no program cache", 0), 0u);
}
