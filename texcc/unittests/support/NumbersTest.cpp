// fitsInFloat / fitsInInt32 at their exact limits.
#include "texcc/Support/Numbers.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

TEST(Numbers, FloatLimitIsTheRoundingMidpoint) {
  EXPECT_TRUE(texcc::fitsInFloat(FLT_MAX));
  EXPECT_TRUE(texcc::fitsInFloat(-FLT_MAX));
  EXPECT_TRUE(texcc::fitsInFloat(3.4028235e38)); // FLT_MAX printed with 8 digits
  EXPECT_EQ(static_cast<float>(3.4028235e38), FLT_MAX);
  const double Midpoint = 0x1.ffffffp127; // rounds (to even) to infinity
  EXPECT_FALSE(texcc::fitsInFloat(Midpoint));
  EXPECT_TRUE(texcc::fitsInFloat(std::nextafter(Midpoint, 0.0)));
  EXPECT_EQ(static_cast<float>(std::nextafter(Midpoint, 0.0)), FLT_MAX);
  EXPECT_FALSE(texcc::fitsInFloat(3.4028236e38));
  EXPECT_FALSE(texcc::fitsInFloat(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(texcc::fitsInFloat(std::nan("")));
  EXPECT_TRUE(texcc::fitsInFloat(0.0));
}

TEST(Numbers, Int32LimitsAreBothEnds) {
  EXPECT_TRUE(texcc::fitsInInt32(-2147483648.0));
  EXPECT_TRUE(texcc::fitsInInt32(2147483647.0));
  EXPECT_FALSE(texcc::fitsInInt32(-2147483649.0));
  EXPECT_FALSE(texcc::fitsInInt32(2147483648.0));
  EXPECT_FALSE(texcc::fitsInInt32(2.5));
  EXPECT_FALSE(texcc::fitsInInt32(std::nan("")));
  EXPECT_FALSE(texcc::fitsInInt32(std::numeric_limits<double>::infinity()));
}
