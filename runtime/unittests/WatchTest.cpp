// texrender --watch's reduced first pass: the pass-time model and the reduction factor it picks
// (PassTimes, Watch.h; docs/live.md).
#include "texrender/Watch.h"

#include <gtest/gtest.h>

using namespace texrender;

TEST(PassTimesTest, NothingRecordedIsHalfSize) {
  PassTimes T;
  EXPECT_LT(T.predict(1000), 0);
  EXPECT_EQ(T.factor(256, 256, 0.060), 2);
}

TEST(PassTimesTest, OneSizeScalesThroughTheOrigin) {
  PassTimes T;
  T.record(65536, 0.640); // 256x256 in 640 ms: 10 us a pixel, no fixed cost known
  EXPECT_NEAR(T.predict(16384), 0.160, 1e-9);
  // 128x128: 160 ms, 64x64: 40 ms <= 60 ms.
  EXPECT_EQ(T.factor(256, 256, 0.060), 4);
}

TEST(PassTimesTest, TwoSizesGiveTheFixedCost) {
  PassTimes T;
  T.record(65536, 0.030 + 65536 * 10e-6);
  T.record(4096, 0.030 + 4096 * 10e-6);
  EXPECT_NEAR(T.predict(1024), 0.030 + 1024 * 10e-6, 1e-9);
  // 64x64: 71 ms > 60 ms; 32x32: 40 ms.
  EXPECT_EQ(T.factor(256, 256, 0.060), 8);
  // A budget under the fixed cost: the coarsest factor.
  EXPECT_EQ(T.factor(256, 256, 0.020), 16);
  // A generous one: half size.
  EXPECT_EQ(T.factor(256, 256, 1.0), 2);
}

TEST(PassTimesTest, SlowerPassesGoCoarser) {
  PassTimes T;
  // An idle machine: 30 ms a pass plus 2 us a pixel; 128x128 would take 62.8 ms, 64x64 38 ms.
  T.record(65536, 0.030 + 65536 * 2e-6);
  T.record(4096, 0.030 + 4096 * 2e-6);
  EXPECT_EQ(T.factor(256, 256, 0.060), 4);
  // Under load the same passes take 10 us a pixel: after a few of each size, 1/8.
  for (int I = 0; I < 6; ++I) {
    T.record(65536, 0.030 + 65536 * 10e-6);
    T.record(4096, 0.030 + 4096 * 10e-6);
  }
  EXPECT_EQ(T.factor(256, 256, 0.060), 8);
}

TEST(PassTimesTest, NewTimesWeighHalf) {
  PassTimes T;
  T.record(100, 1.0);
  T.record(100, 3.0);
  EXPECT_NEAR(T.predict(100), 2.0, 1e-12);
}

TEST(PassTimesTest, NoiseNeverPredictsASmallerPassSlowerThanSeen) {
  PassTimes T;
  T.record(65536, 0.5);
  T.record(4096, 0.6); // the small pass met a busier machine
  EXPECT_NEAR(T.predict(1024), 0.6, 1e-12);
  EXPECT_EQ(T.factor(256, 256, 0.060), 16);
}

TEST(PassTimesTest, FactorKeepsOnePixelASide) {
  PassTimes T;
  T.record(64, 10.0);
  // 6x3: 1/2 is 3x2, 1/4 is 2x1, 1/8 would be 1x1; nothing fits, so the last tried.
  EXPECT_EQ(T.factor(6, 3, 0.001), 8);
  EXPECT_EQ(T.factor(2, 2, 0.001), 2);
}
