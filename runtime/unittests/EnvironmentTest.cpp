// The environment map's density (runtime/lib/Environment.cpp, read by kernels/common/rt_env.h):
// a density over (u, v) that integrates to 1, CDFs that end at 1, rows in Cycles' order (row 0
// the image's bottom), and support wherever the bilinear lookup has radiance.
#include "texrender/Environment.h"
#include "texrender/Error.h"
#include "texrender/Image.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

extern "C" {
#include "rt_types.h"
}

namespace fs = std::filesystem;
using namespace texrender;

namespace {
/// An environment light of a W x H EXR, black but for texel (X, Y) (Y from the top) of value V.
EnvironmentMap oneHot(int W, int H, int X, int Y, float V, const std::string &Interp) {
  fs::path P = fs::temp_directory_path() /
               ("texrender-env-" + std::to_string(::getpid()) + "-" + Interp + ".exr");
  std::vector<float> RGB(size_t(W) * H * 3, 0.0f);
  for (int C = 0; C < 3; ++C)
    RGB[(size_t(Y) * W + X) * 3 + C] = V;
  writeImage(P.string(), W, H, RGB);
  Light L;
  L.Type = "environment";
  L.Image = P.string();
  L.Interpolation = Interp;
  EnvironmentMap M = loadEnvironmentMap(L, "scene.json: /lights/0");
  fs::remove(P);
  return M;
}

float density(const EnvironmentMap &M, int X, int Row) {
  return M.Data[4 * (size_t(Row) * M.Width + X) + 3];
}
} // namespace

TEST(Environment, DensityIntegratesToOneAndCdfsEndAtOne) {
  EnvironmentMap M = oneHot(16, 8, 5, 2, 100.0f, "linear");
  ASSERT_EQ(M.Data.size(), size_t(16 * 8 * 4 + 8 + 16 * 8));
  double Sum = 0;
  for (int R = 0; R < 8; ++R)
    for (int X = 0; X < 16; ++X)
      Sum += density(M, X, R);
  EXPECT_NEAR(Sum / (16 * 8), 1.0, 1e-5);
  const float *Marginal = &M.Data[16 * 8 * 4];
  EXPECT_EQ(Marginal[7], 1.0f);
  for (int R = 0; R < 8; ++R) {
    EXPECT_EQ(Marginal[8 + R * 16 + 15], 1.0f) << R;
    for (int X = 1; X < 16; ++X)
      EXPECT_LE(Marginal[8 + R * 16 + X - 1], Marginal[8 + R * 16 + X]);
  }
  EXPECT_EQ(M.Flags, 0);
  EXPECT_EQ(M.Width, 16);
}

TEST(Environment, LinearSpreadsTheDensityAsFarAsTheLookup) {
  // Texel (5, 2) from the top is row 8 - 1 - 2 = 5 from the bottom (Cycles' v = 0).
  EnvironmentMap M = oneHot(16, 8, 5, 2, 100.0f, "linear");
  EXPECT_GT(density(M, 5, 5), 0.0f);
  for (int DX = -1; DX <= 1; ++DX)
    for (int DY = -1; DY <= 1; ++DY)
      EXPECT_GT(density(M, 5 + DX, 5 + DY), 0.0f) << DX << " " << DY;
  EXPECT_GT(density(M, 5, 5), 4 * density(M, 6, 5));
  EXPECT_EQ(density(M, 7, 5), 0.0f);
  EXPECT_EQ(density(M, 5, 3), 0.0f);
  EXPECT_EQ(M.Data[4 * (5 * 16 + 5)], 100.0f); // the texel, bottom-up
}

TEST(Environment, ClosestKeepsTheDensityOnTheTexel) {
  EnvironmentMap M = oneHot(16, 8, 0, 7, 50.0f, "closest");
  EXPECT_EQ(M.Flags, RT_ENV_CLOSEST);
  EXPECT_NEAR(density(M, 0, 0), 16 * 8, 1e-2); // all of it on one texel
  EXPECT_EQ(density(M, 15, 0), 0.0f);
  EXPECT_EQ(density(M, 0, 1), 0.0f);
}

TEST(Environment, BlackMapHasAUniformDensity) {
  EnvironmentMap M = oneHot(8, 4, 0, 0, 0.0f, "linear");
  EXPECT_EQ(M.MeanLuminance, 0.0);
  double Sum = 0;
  for (int R = 0; R < 4; ++R)
    for (int X = 0; X < 8; ++X) {
      EXPECT_GT(density(M, X, R), 0.0f);
      Sum += density(M, X, R);
    }
  EXPECT_NEAR(Sum / 32, 1.0, 1e-5);
}

TEST(Environment, MissingImageNamesTheJsonPath) {
  Light L;
  L.Type = "environment";
  L.Image = "/nonexistent/sky.exr";
  try {
    loadEnvironmentMap(L, "scene.json: /lights/2");
    FAIL() << "no error";
  } catch (const Error &E) {
    EXPECT_EQ(std::string(E.what()).rfind("scene.json: /lights/2/image: /nonexistent/sky.exr", 0),
              0u)
        << E.what();
  }
}
