#include "texcc/Version.h"

#include <gtest/gtest.h>

#include <cstring>

TEST(Version, IsSemantic) {
  const char *V = texcc::versionString();
  ASSERT_NE(V, nullptr);
  EXPECT_EQ(std::count(V, V + std::strlen(V), '.'), 2);
}
