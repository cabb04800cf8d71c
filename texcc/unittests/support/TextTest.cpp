// boundedExcerpt / boundedMessage: what a diagnostic quotes stays bounded (issue 40, item 8).
#include "texcc/Support/Text.h"

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(BoundedExcerpt, ShortTextIsKept) {
  EXPECT_EQ(texcc::boundedExcerpt("abc", 80), "abc");
  EXPECT_EQ(texcc::boundedExcerpt("a\nb\tc\x01", 80), "a\\nb\\tc\\x01");
}

TEST(BoundedExcerpt, LongTextKeepsHeadTailAndSize) {
  const std::string Long = "HEAD" + std::string(1000000, 'x') + "TAIL";
  const std::string E = texcc::boundedExcerpt(Long, 80);
  EXPECT_LE(E.size(), 80u);
  EXPECT_EQ(E.rfind("HEAD", 0), 0u);
  EXPECT_NE(E.find("TAIL (1000008 bytes)"), std::string::npos);
  EXPECT_NE(E.find("..."), std::string::npos);
  // Quoted again, an excerpt is left as it is.
  EXPECT_EQ(texcc::boundedExcerpt(E, 80), E);
}

TEST(BoundedExcerpt, NeverSplitsUtf8) {
  std::string Long;
  for (int I = 0; I < 1000; ++I)
    Long += "\xc3\xa9"; // é
  const std::string E = texcc::boundedExcerpt(Long, 41);
  const size_t Dots = E.find("...");
  ASSERT_NE(Dots, std::string::npos);
  EXPECT_EQ(Dots % 2, 0u);                          // whole sequences before the dots
  EXPECT_NE(static_cast<unsigned char>(E[Dots + 3]), 0xa9u); // and after them
}

TEST(BoundedMessage, LongQuotesAndPointersAreCut) {
  const std::string Name(10000000, 'q');
  const std::string M = texcc::boundedMessage("unknown key '" + Name + "' in graph [/" + Name +
                                              "]; got \"" + Name + "\"");
  EXPECT_LT(M.size(), 1000u);
  EXPECT_EQ(M.rfind("unknown key 'qqq", 0), 0u);
  EXPECT_NE(M.find(" (10000000 bytes)' in graph [/"), std::string::npos);
  EXPECT_NE(M.find(" (10000001 bytes)]; got \""), std::string::npos);
  // A short message, and one with short quotes, is unchanged.
  EXPECT_EQ(texcc::boundedMessage("node 'n': unknown function 'f' [/nodes/0/fn]"),
            "node 'n': unknown function 'f' [/nodes/0/fn]");
}

TEST(BoundedMessage, LongLinesAreCutLineByLine) {
  const std::string M = texcc::boundedMessage("first\n" + std::string(100000, 'z') + "\nlast");
  EXPECT_EQ(M.rfind("first\nzzz", 0), 0u);
  EXPECT_NE(M.find(" (100000 bytes)\nlast"), std::string::npos);
  EXPECT_LT(M.size(), 4200u);
}

} // namespace
