// Image files: PNG out (sRGB) and back in as a texture (linear), EXR round trip, edit parsing.
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texrender/LiveEdit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

namespace {
fs::path tempFile(const std::string &Name) {
  return fs::temp_directory_path() / ("texrender-img-" + std::to_string(::getpid()) + "-" + Name);
}
} // namespace

TEST(Image, SrgbRoundTrip) {
  for (float V : {0.0f, 0.001f, 0.05f, 0.2f, 0.5f, 1.0f})
    EXPECT_NEAR(srgbToLinear(linearToSrgb(V)), V, 1e-5);
  EXPECT_NEAR(linearToSrgb(0.5f), 0.7354f, 1e-3);
}

TEST(Image, PngIsSrgbAndTexturesAreLinear) {
  fs::path P = tempFile("a.png");
  std::vector<float> RGB = {0.0f, 0.2f, 1.0f, 0.5f, 0.5f, 0.5f};
  writeImage(P.string(), 2, 1, RGB);
  ImageRGBA T = loadTexture(P.string());
  ASSERT_EQ(T.Width, 2);
  ASSERT_EQ(T.Height, 1);
  for (int I = 0; I < 2; ++I) {
    for (int C = 0; C < 3; ++C)
      EXPECT_NEAR(T.Pixels[4 * I + C], RGB[3 * I + C], 0.01) << I << " " << C;
    EXPECT_FLOAT_EQ(T.Pixels[4 * I + 3], 1.0f);
  }
}

TEST(Image, ExrIsLinearFloat) {
  fs::path P = tempFile("a.exr");
  std::vector<float> RGB = {0.0f, 12.5f, 0.001f, 3.0f, 1e-4f, 0.25f};
  writeImage(P.string(), 1, 2, RGB);
  ImageRGBA T = loadExr(P.string());
  ASSERT_EQ(T.Width, 1);
  ASSERT_EQ(T.Height, 2);
  for (int I = 0; I < 2; ++I)
    for (int C = 0; C < 3; ++C)
      EXPECT_FLOAT_EQ(T.Pixels[4 * I + C], RGB[3 * I + C]);
}

TEST(Image, UnknownFormatAndMissingFileAreErrors) {
  EXPECT_THROW(writeImage(tempFile("a.jpg").string(), 1, 1, {0, 0, 0}), Error);
  EXPECT_THROW(loadTexture("/nonexistent/t.png"), Error);
}

TEST(Edit, Parses) {
  Edit A = parseEdit("set n.scale=2.5");
  EXPECT_EQ(A.K, Edit::Kind::Set);
  EXPECT_EQ(A.Node, "n");
  EXPECT_EQ(A.Arg, "scale");
  EXPECT_EQ(A.Value, "2.5");
  Edit B = parseEdit("  ramp.stops = [[0,1,0,0],[1,0,0,1]] ");
  EXPECT_EQ(B.Node, "ramp");
  EXPECT_EQ(B.Value, "[[0,1,0,0],[1,0,0,1]]");
  Edit C = parseEdit("rewire mask.noise=grain");
  EXPECT_EQ(C.K, Edit::Kind::Rewire);
  EXPECT_EQ(C.Value, "grain");
  EXPECT_THROW(parseEdit("n.scale"), Error);
  EXPECT_THROW(parseEdit("scale=1"), Error);
  EXPECT_THROW(parseEdit("n.scale="), Error);
}

// Edit-script diagnostics point at the part at fault: 1-based columns in the line as written.
TEST(Edit, KeepsColumns) {
  Edit A = parseEdit("  rewire a.b = c");
  EXPECT_EQ(A.NodeCol, 10u);
  EXPECT_EQ(A.ArgCol, 12u);
  EXPECT_EQ(A.ValueCol, 16u);
  Edit B = parseEdit("node.arg=[1,2]");
  EXPECT_EQ(B.NodeCol, 1u);
  EXPECT_EQ(B.ArgCol, 6u);
  EXPECT_EQ(B.ValueCol, 10u);
}
