// readRegularFile / checkRegularFile: a regular file is read whole; anything else is refused at
// once with its reason, and never blocks (a FIFO without a writer).
#include "texcc/Support/File.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

class FileTest : public ::testing::Test {
protected:
  void SetUp() override {
    std::string Template = (fs::temp_directory_path() / "texcc-file-test-XXXXXX").string();
    ASSERT_NE(::mkdtemp(Template.data()), nullptr);
    Dir = Template;
  }
  void TearDown() override {
    std::error_code EC;
    fs::remove_all(Dir, EC);
  }
  std::string path(const std::string &Name) const { return (fs::path(Dir) / Name).string(); }
  std::string Dir;
};

TEST_F(FileTest, ReadsARegularFileWhole) {
  std::string Bytes("a\0b\n", 4);
  std::ofstream(path("f"), std::ios::binary) << Bytes;
  std::string Text, Why;
  ASSERT_TRUE(texcc::readRegularFile(path("f"), Text, Why)) << Why;
  EXPECT_EQ(Text, Bytes);
  EXPECT_TRUE(texcc::checkRegularFile(path("f"), Why));
}

TEST_F(FileTest, ReadsAnEmptyFile) {
  std::ofstream(path("empty")).close();
  std::string Text = "old", Why;
  ASSERT_TRUE(texcc::readRegularFile(path("empty"), Text, Why)) << Why;
  EXPECT_EQ(Text, "");
}

TEST_F(FileTest, RefusesAFifoWithoutBlocking) {
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  std::string Text, Why;
  EXPECT_FALSE(texcc::readRegularFile(path("fifo"), Text, Why));
  EXPECT_EQ(Why, "it is a FIFO, not a regular file");
  EXPECT_FALSE(texcc::checkRegularFile(path("fifo"), Why));
  EXPECT_EQ(Why, "it is a FIFO, not a regular file");
}

TEST_F(FileTest, RefusesAFolder) {
  std::string Text, Why;
  EXPECT_FALSE(texcc::readRegularFile(Dir, Text, Why));
  EXPECT_EQ(Why, "it is a folder");
}

TEST_F(FileTest, RefusesADevice) {
  std::string Text, Why;
  EXPECT_FALSE(texcc::readRegularFile("/dev/zero", Text, Why));
  EXPECT_EQ(Why, "it is a device, not a regular file");
}

TEST_F(FileTest, NamesAMissingFileAndASymlinkLoop) {
  std::string Text, Why;
  EXPECT_FALSE(texcc::readRegularFile(path("missing"), Text, Why));
  EXPECT_EQ(Why, "no such file");
  fs::create_symlink("loop", path("loop"));
  EXPECT_FALSE(texcc::readRegularFile(path("loop"), Text, Why));
  EXPECT_EQ(Why, "too many levels of symbolic links");
}

TEST_F(FileTest, FollowsASymlinkToARegularFile) {
  std::ofstream(path("target")) << "x";
  fs::create_symlink("target", path("link"));
  std::string Text, Why;
  ASSERT_TRUE(texcc::readRegularFile(path("link"), Text, Why)) << Why;
  EXPECT_EQ(Text, "x");
}

} // namespace
