// writeFileAtomically / writeAtomicallyWith: the new contents appear in one step, a failed
// write leaves the old file and no temporary, and removeStaleTemporaries recognises the
// temporaries of a dead process.
#include "texcc/StaleTemporaries.h"
#include "texcc/Support/AtomicWrite.h"
#include "texcc/Support/File.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

class AtomicWriteTest : public ::testing::Test {
protected:
  void SetUp() override {
    std::string Template = (fs::temp_directory_path() / "texcc-atomic-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(Template.data()), nullptr);
    Dir = Template;
  }
  void TearDown() override {
    std::error_code EC;
    fs::remove_all(Dir, EC);
  }
  std::string path(const std::string &Name) const { return (fs::path(Dir) / Name).string(); }
  std::string contents(const std::string &Name) const {
    std::string Text, Why;
    EXPECT_TRUE(texcc::readRegularFile(path(Name), Text, Why)) << Why;
    return Text;
  }
  /// Names in Dir, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> Names;
    for (const auto &E : fs::directory_iterator(Dir))
      Names.push_back(E.path().filename().string());
    std::sort(Names.begin(), Names.end());
    return Names;
  }
  std::string Dir;
};

TEST_F(AtomicWriteTest, WritesAndReplacesWithNoTemporaryLeft) {
  std::string Why;
  ASSERT_TRUE(texcc::writeFileAtomically(path("a.bin"), std::string("x\0y", 3), Why)) << Why;
  EXPECT_EQ(contents("a.bin"), std::string("x\0y", 3));
  ASSERT_TRUE(texcc::writeFileAtomically(path("a.bin"), "second", Why)) << Why;
  EXPECT_EQ(contents("a.bin"), "second");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.bin"});
}

TEST_F(AtomicWriteTest, AFailedWriteKeepsTheOldFile) {
  std::string Why;
  ASSERT_TRUE(texcc::writeFileAtomically(path("a.txt"), "old", Why)) << Why;
  std::string SeenTemp;
  EXPECT_FALSE(texcc::writeAtomicallyWith(
      path("a.txt"),
      [&](const std::string &Temp, std::string &W) {
        SeenTemp = Temp;
        std::ofstream(Temp) << "half";
        W = "disk full";
        return false;
      },
      Why));
  EXPECT_EQ(Why, "disk full");
  EXPECT_EQ(fs::path(SeenTemp).parent_path(), fs::path(Dir));
  EXPECT_EQ(fs::path(SeenTemp).filename().string().rfind(".a.txt.tmp", 0), 0u);
  EXPECT_THROW(texcc::writeAtomicallyWith(
                   path("a.txt"),
                   [](const std::string &Temp, std::string &) -> bool {
                     std::ofstream(Temp) << "half";
                     throw std::runtime_error("writer failed");
                   },
                   Why),
               std::runtime_error);
  EXPECT_EQ(contents("a.txt"), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicWriteTest, AMissingFolderIsAnError) {
  std::string Why;
  EXPECT_FALSE(texcc::writeFileAtomically(path("no/such/dir/a.txt"), "x", Why));
  EXPECT_FALSE(Why.empty());
}

// /dev/full: every write fails with ENOSPC, as on a full disk. writeWholeFile reports it (stdio
// lost it when fclose()'s result went unchecked, tinyexr's case).
TEST_F(AtomicWriteTest, AFullDeviceIsAWriteError) {
  std::string Why;
  const std::string Big(1 << 20, 'x');
  EXPECT_FALSE(texcc::writeWholeFile("/dev/full", Big.data(), Big.size(), Why));
  EXPECT_EQ(Why, "No space left on device");
  Why.clear();
  EXPECT_FALSE(texcc::writeWholeFile("/dev/full", "x", 1, Why));
  EXPECT_EQ(Why, "No space left on device");
}

// A device as the target is refused before anything is written beside it (renaming over it
// would replace the device).
TEST_F(AtomicWriteTest, ADeviceTargetIsRefused) {
  std::string Why;
  EXPECT_FALSE(texcc::checkReplaceable("/dev/full", Why));
  EXPECT_EQ(Why, "it is a device, not a regular file");
  Why.clear();
  EXPECT_FALSE(texcc::checkReplaceable(Dir, Why));
  EXPECT_EQ(Why, "it is a folder");
  EXPECT_TRUE(texcc::checkReplaceable(path("new.txt"), Why));
}

TEST_F(AtomicWriteTest, StaleTemporariesOfADeadProcessAreRemoved) {
  // pid 999999999 cannot exist (pid_max is at most 2^22); this process's own are kept.
  const std::string Mine = ".a.txt.tmp" + std::to_string(::getpid()) + ".3";
  for (const std::string &Name : {std::string(".a.txt.tmp999999999"),
                                  std::string(".a.txt.tmp999999999.2"), Mine,
                                  std::string(".a.txt.tmp999999999.x")})
    std::ofstream(path(Name)) << "t";
  texcc::removeStaleTemporaries(Dir, {"a.txt"});
  std::vector<std::string> Kept = {".a.txt.tmp999999999.x", Mine};
  std::sort(Kept.begin(), Kept.end());
  EXPECT_EQ(entries(), Kept);
}

} // namespace
