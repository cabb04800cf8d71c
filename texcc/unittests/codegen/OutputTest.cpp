// Atomic output: all files appear together, an error leaves the old ones and no temporaries.
#include "texcc/Codegen/Codegen.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace texcc::codegen;

namespace {

std::string readAll(const fs::path &P) {
  std::ifstream IS(P, std::ios::binary);
  std::ostringstream SS;
  SS << IS.rdbuf();
  return SS.str();
}

fs::path freshDir(const std::string &Name) {
  fs::path Dir = fs::temp_directory_path() / ("texcc-codegen-test-" + Name);
  fs::remove_all(Dir);
  return Dir;
}

TEST(CodegenOutput, WritesEveryFileAndNoTemporaries) {
  fs::path Dir = freshDir("write");
  std::string Error;
  ASSERT_TRUE(writeOutputsAtomically(Dir.string(), {{"a.txt", "A"}, {"b.bin", std::string("\0B", 2)}},
                                     Error))
      << Error;
  EXPECT_EQ(readAll(Dir / "a.txt"), "A");
  EXPECT_EQ(readAll(Dir / "b.bin"), std::string("\0B", 2));
  size_t Count = 0;
  for (const auto &Entry : fs::directory_iterator(Dir)) {
    (void)Entry;
    ++Count;
  }
  EXPECT_EQ(Count, 2u);
  fs::remove_all(Dir);
}

TEST(CodegenOutput, AFailedWriteLeavesTheOldOutputs) {
  fs::path Dir = freshDir("fail");
  std::string Error;
  ASSERT_TRUE(writeOutputsAtomically(Dir.string(), {{"a.txt", "old"}}, Error)) << Error;
  // A folder in the way of the second file makes the run fail before anything is replaced.
  fs::create_directories(Dir / "b.txt" / "blocker");
  EXPECT_FALSE(writeOutputsAtomically(Dir.string(), {{"a.txt", "new"}, {"b.txt", "B"}}, Error));
  EXPECT_FALSE(Error.empty()) << Error;
  EXPECT_EQ(readAll(Dir / "a.txt"), "old");
  for (const auto &Entry : fs::directory_iterator(Dir))
    EXPECT_EQ(Entry.path().filename().string().find(".tmp"), std::string::npos)
        << Entry.path();
  fs::remove_all(Dir);
}

} // namespace
