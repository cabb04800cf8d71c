// A frame in lanes (Lanes.h) against the whole frame on one Renderer, on a floor and a cube
// under the cornell layout (skipped without an OpenCL device that splits into two lanes): the
// same image and variance bytes with two and three lanes and a region; and a frame stopped by
// AfterPass ends every lane at the same sample count, equal bit for bit to a render of that many
// samples.
#include "texrender/Error.h"
#include "texrender/Lanes.h"
#include "texrender/Layout.h"
#include "texrender/Renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

std::string sourceDir() {
  if (const char *S = std::getenv("TEXCC_SRC"))
    return S;
  return TEXRENDER_SOURCE_DIR;
}

struct TestScene {
  Scene S;
  Layout L;
};

TestScene floorAndCube(int Width, int Height, int Spp) {
  fs::path Dir = fs::temp_directory_path() / ("texrender-lanes-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  TestScene T;
  T.L = loadLayout(sourceDir() + "/testsuite/Inputs/runtime/cornell-tex");
  T.S.Path = (Dir / "scene.json").string();
  T.S.Cam.Position = {0.0f, 1.5f, 3.0f};
  T.S.Cam.Target = {0.0f, 0.0f, 0.0f};
  T.S.Cam.FovDegrees = 50;
  T.S.Render.Width = Width, T.S.Render.Height = Height, T.S.Render.Spp = Spp;
  T.S.Render.MaxDepth = 4;
  fs::path P = Dir / "m.obj";
  std::ofstream(P) << "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\nvn 0 1 0\nf 1//1 4//1 3//1 2//1\n"
                      "v -0.4 0 -0.4\nv 0.4 0 -0.4\nv 0.4 0 0.4\nv -0.4 0 0.4\n"
                      "v -0.4 0.8 -0.4\nv 0.4 0.8 -0.4\nv 0.4 0.8 0.4\nv -0.4 0.8 0.4\n"
                      "f 9 10 11 12\nf 5 6 10 9\nf 6 7 11 10\nf 7 8 12 11\nf 8 5 9 12\n";
  MeshInstance M;
  M.ObjPath = P.string();
  M.Material = "white";
  M.Transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  M.JsonPath = "/meshes/0";
  T.S.Meshes.push_back(M);
  return T;
}

RendererOptions testOptions() {
  RendererOptions O;
  O.CacheDir = (fs::temp_directory_path() / "texrender-test-cache").string();
  O.QuickFirstBuild = false;
  if (!std::getenv("TEXRENDER_KERNELS"))
    O.KernelDir = TEXRENDER_KERNEL_DIR;
  return O;
}

/// Lanes the default device splits into (0 without a device).
unsigned laneCapacity() {
  if (listDevices().empty())
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
      RendererOptions O = testOptions();
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
  RendererOptions O = testOptions();
  O.MaxPathsPerPass = size_t(W) * H; // one sample per pixel a pass
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
  EXPECT_EQ(Stopped.Passes, unsigned(Stopped.SamplesDone));
  // The image is that of a render asked for that many samples, on one renderer.
  T.S.Render.Spp = Stopped.SamplesDone;
  RendererOptions Plain = testOptions();
  Plain.MaxPathsPerPass = O.MaxPathsPerPass;
  Renderer Whole(T.S, T.L, Plain);
  FrameStats WholeStats;
  EXPECT_EQ(Whole.render(WholeStats), Image);
}

TEST(Lanes, UnavailableSaysWhy) {
  if (laneCapacity() < 2)
    GTEST_SKIP() << "no OpenCL device that splits into two lanes";
  TestScene T = floorAndCube(8, 3, 1);
  RendererOptions O = testOptions();
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
