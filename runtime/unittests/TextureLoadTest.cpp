// Textures in: 8- and 16-bit PNG, JPEG, Radiance HDR and float EXR, each generated here, read in
// each colour space (graph.md "Images"); the values are checked exactly.
#include "texrender/Error.h"
#include "texrender/Image.h"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

fs::path tempFile(const std::string &Name) {
  return fs::temp_directory_path() / ("texrender-tex-" + std::to_string(::getpid()) + "-" + Name);
}

/// 4 texels RGBA 8-bit: colour steps across the range, alpha 255 except one texel at 128.
const unsigned char Bytes8[16] = {0, 10, 128, 255, 200, 255, 1, 128, 64, 32, 16, 255, 255, 254, 100, 255};

/// A 16-bit RGBA PNG (stb_image_write has only 8-bit): big-endian samples, filter 0 rows.
void writePng16(const fs::path &P, int W, int H, const std::vector<uint16_t> &RGBA) {
  std::vector<unsigned char> Raw;
  for (int Y = 0; Y < H; ++Y) {
    Raw.push_back(0);
    for (int I = 0; I < W * 4; ++I) {
      uint16_t V = RGBA[size_t(Y) * W * 4 + I];
      Raw.push_back(V >> 8);
      Raw.push_back(V & 0xff);
    }
  }
  uLongf Len = compressBound(Raw.size());
  std::vector<unsigned char> Z(Len);
  ASSERT_EQ(compress(Z.data(), &Len, Raw.data(), Raw.size()), Z_OK);
  Z.resize(Len);
  std::ofstream Out(P, std::ios::binary);
  auto U32 = [&](uint32_t V) {
    unsigned char B[4] = {(unsigned char)(V >> 24), (unsigned char)(V >> 16), (unsigned char)(V >> 8), (unsigned char)V};
    Out.write(reinterpret_cast<char *>(B), 4);
  };
  auto Chunk = [&](const char *Type, const std::vector<unsigned char> &Data) {
    U32(uint32_t(Data.size()));
    std::vector<unsigned char> T(Type, Type + 4);
    T.insert(T.end(), Data.begin(), Data.end());
    Out.write(reinterpret_cast<const char *>(T.data()), T.size());
    U32(uint32_t(crc32(0, T.data(), T.size())));
  };
  Out.write("\x89PNG\r\n\x1a\n", 8);
  std::vector<unsigned char> Ihdr = {0, 0, 0, (unsigned char)W, 0, 0, 0, (unsigned char)H, 16, 6, 0, 0, 0};
  Chunk("IHDR", Ihdr);
  Chunk("IDAT", Z);
  Chunk("IEND", {});
}

} // namespace

TEST(TextureLoad, Png8InEachColorSpace) {
  fs::path P = tempFile("a.png");
  ASSERT_TRUE(stbi_write_png(P.c_str(), 2, 2, 4, Bytes8, 8));
  for (std::string Cs : {"", "sRGB", "Linear Rec.709", "Non-Color"}) {
    ImageRGBA T = loadTexture(P.string(), Cs);
    EXPECT_EQ(T.ColorSpace, Cs.empty() ? "sRGB" : Cs);
    ASSERT_EQ(T.Width, 2);
    ASSERT_EQ(T.Height, 2);
    for (int I = 0; I < 16; ++I) {
      float Stored = Bytes8[I] / 255.0f;
      bool Decode = (Cs.empty() || Cs == "sRGB") && I % 4 != 3;
      EXPECT_EQ(T.Pixels[I], Decode ? srgbToLinear(Stored) : Stored) << Cs << " " << I;
    }
  }
  fs::remove(P);
}

TEST(TextureLoad, Png16KeepsSixteenBits) {
  fs::path P = tempFile("b.png");
  // Values one apart, which 8 bits would merge; the alpha of texel 1 below 1.
  std::vector<uint16_t> V = {0, 1, 32768, 65535, 65534, 257, 12345, 40000};
  writePng16(P, 2, 1, V);
  for (std::string Cs : {"", "Non-Color"}) {
    ImageRGBA T = loadTexture(P.string(), Cs);
    ASSERT_EQ(T.Width, 2);
    ASSERT_EQ(T.Height, 1);
    EXPECT_EQ(T.ColorSpace, Cs.empty() ? "sRGB" : Cs);
    for (int I = 0; I < 8; ++I) {
      float Stored = V[I] / 65535.0f;
      EXPECT_EQ(T.Pixels[I], Cs.empty() && I % 4 != 3 ? srgbToLinear(Stored) : Stored) << I;
    }
  }
  fs::remove(P);
}

TEST(TextureLoad, JpegFlatGreysAreExact) {
  // Flat 8x8 blocks of grey: only the DC term, no chroma, so every decoder gives the bytes back.
  fs::path P = tempFile("c.jpg");
  std::vector<unsigned char> Px(16 * 8 * 3);
  for (int Y = 0; Y < 8; ++Y)
    for (int X = 0; X < 16; ++X)
      for (int C = 0; C < 3; ++C)
        Px[(Y * 16 + X) * 3 + C] = X < 8 ? 200 : 37;
  ASSERT_TRUE(stbi_write_jpg(P.c_str(), 16, 8, 3, Px.data(), 100));
  ImageRGBA S = loadTexture(P.string()), D = loadTexture(P.string(), "Non-Color");
  EXPECT_EQ(S.ColorSpace, "sRGB");
  ASSERT_EQ(S.Width, 16);
  EXPECT_EQ(S.Pixels[0], srgbToLinear(200 / 255.0f));
  EXPECT_EQ(S.Pixels[4 * 15 + 1], srgbToLinear(37 / 255.0f));
  EXPECT_EQ(D.Pixels[0], 200 / 255.0f);
  EXPECT_EQ(D.Pixels[4 * 15 + 2], 37 / 255.0f);
  EXPECT_EQ(D.Pixels[3], 1.0f);
  fs::remove(P);
}

TEST(TextureLoad, FloatFilesAreLinearByDefault) {
  fs::path E = tempFile("d.exr"), H = tempFile("d.hdr");
  std::vector<float> RGB = {0.0f, 12.5f, 0.001f, 0.5f, 0.25f, 2.0f};
  writeImage(E.string(), 2, 1, RGB);
  ImageRGBA T = loadTexture(E.string());
  EXPECT_EQ(T.ColorSpace, "Linear Rec.709");
  ASSERT_EQ(T.Width, 2);
  for (int I = 0; I < 2; ++I) {
    for (int C = 0; C < 3; ++C)
      EXPECT_EQ(T.Pixels[4 * I + C], RGB[3 * I + C]);
    EXPECT_EQ(T.Pixels[4 * I + 3], 1.0f);
  }
  // Marked sRGB, a float image's values are decoded too (Blender does; above 1 as the curve goes).
  ImageRGBA S = loadTexture(E.string(), "sRGB");
  for (int I = 0; I < 2; ++I)
    for (int C = 0; C < 3; ++C)
      EXPECT_EQ(S.Pixels[4 * I + C], srgbToLinear(RGB[3 * I + C]));
  // Radiance HDR: linear too (its values are what stb's RGBE rounding keeps; 0.5 and 2 are exact).
  ASSERT_TRUE(stbi_write_hdr(H.c_str(), 2, 1, 3, RGB.data()));
  ImageRGBA R = loadTexture(H.string());
  EXPECT_EQ(R.ColorSpace, "Linear Rec.709");
  EXPECT_EQ(R.Pixels[4 + 0], 0.5f);
  EXPECT_EQ(R.Pixels[4 + 2], 2.0f);
  fs::remove(E);
  fs::remove(H);
}

TEST(TextureLoad, UnknownColorSpaceIsAnError) {
  fs::path P = tempFile("e.png");
  ASSERT_TRUE(stbi_write_png(P.c_str(), 2, 2, 4, Bytes8, 8));
  try {
    loadTexture(P.string(), "Raw");
    FAIL() << "no error";
  } catch (const Error &E) {
    EXPECT_NE(std::string(E.what()).find("unknown colour space 'Raw'"), std::string::npos) << E.what();
    EXPECT_NE(std::string(E.what()).find("'Non-Color'"), std::string::npos) << E.what();
  }
  fs::remove(P);
}
