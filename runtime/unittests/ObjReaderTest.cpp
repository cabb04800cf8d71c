// loadObj's fast reader (ObjLoader.cpp): where it accepts a text it must give the full reader's
// (tinyobjloader's) mesh bit for bit, and it must decline what it does not read the same way.
#include "texrender/Error.h"
#include "texrender/Scene.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

/// The mesh or the error message of one reader.
struct Outcome {
  bool Declined = false;
  std::string Error;
  TriangleMesh Mesh;
};

Outcome fast(const std::string &Text) {
  Outcome O;
  try {
    std::optional<TriangleMesh> M = objFromTextFast("t.obj", Text);
    O.Declined = !M;
    if (M)
      O.Mesh = std::move(*M);
  } catch (const Error &E) {
    O.Error = E.what();
  }
  return O;
}

Outcome full(const std::string &Text) {
  Outcome O;
  try {
    O.Mesh = objFromTextFull("t.obj", Text);
  } catch (const Error &E) {
    O.Error = E.what();
  }
  return O;
}

template <typename T> bool sameBits(const std::vector<T> &A, const std::vector<T> &B) {
  return A.size() == B.size() && (A.empty() || std::memcmp(A.data(), B.data(), A.size() * sizeof(T)) == 0);
}

/// The fast reader accepts Text and gives what the full reader gives (mesh or error).
::testing::AssertionResult acceptsSame(const std::string &Text) {
  Outcome F = fast(Text), G = full(Text);
  if (F.Declined)
    return ::testing::AssertionFailure() << "the fast reader declined:\n" << Text;
  if (F.Error != G.Error)
    return ::testing::AssertionFailure() << "errors differ: '" << F.Error << "' / '" << G.Error
                                         << "'\n" << Text;
  if (!sameBits(F.Mesh.Positions, G.Mesh.Positions) || !sameBits(F.Mesh.Normals, G.Mesh.Normals) ||
      !sameBits(F.Mesh.UVs, G.Mesh.UVs))
    return ::testing::AssertionFailure() << "meshes differ (" << F.Mesh.triangleCount() << " / "
                                         << G.Mesh.triangleCount() << " triangles):\n" << Text;
  return ::testing::AssertionSuccess();
}

std::string readAll(const fs::path &P) {
  gzFile F = gzopen(P.c_str(), "rb");
  std::string Out;
  char Buf[1 << 16];
  int N;
  while (F && (N = gzread(F, Buf, sizeof Buf)) > 0)
    Out.append(Buf, size_t(N));
  if (F)
    gzclose(F);
  return Out;
}

/// A string literal with its NUL bytes.
template <size_t N> std::string withNul(const char (&Lit)[N]) { return std::string(Lit, N - 1); }

/// Whether Text has a statement outside the fast reader's subset that these files use: a
/// polygon of four or more corners, a line or a point.
bool hasPolygonsOrLines(const std::string &Text) {
  std::istringstream In(Text);
  for (std::string Line; std::getline(In, Line);) {
    std::istringstream Words(Line);
    std::string First, W;
    Words >> First;
    int Count = 0;
    while (Words >> W)
      ++Count;
    if (First == "l" || First == "p" || (First == "f" && Count > 3))
      return true;
  }
  return false;
}

} // namespace

TEST(ObjFast, AcceptsTheCommonSubset) {
  // Every construct the fast reader reads: comments, blank lines, CRLF, tabs, groups, objects,
  // smoothing groups, materials, the four corner forms, negative (relative) indices, a forward
  // reference, signs, leading and trailing dots, exponents, vt with a third number.
  const char *Text = "# a comment\r\n"
                     "mtllib none.mtl\n"
                     "o first\n"
                     "\n"
                     "   \t\n"
                     "v 0 0 0\n"
                     "v\t1.5 -0 .25\r\n"
                     "v +2. 1e-2 -3.5E+1\n"
                     "v 0.12345678901 1.000000001 7e3\n"
                     "vt 0 0\n"
                     "vt 1 0 0\n"
                     "vt .5 1\n"
                     "vn 0 1 0\n"
                     "vn 0 0 -1\n"
                     "g a b\n"
                     "usemtl m\n"
                     "s 1\n"
                     "f 1 2 3\n"
                     "f 1/1 2/2 3/3\n"
                     "f 1//1 2//1 3//2\n"
                     "f 1/1/1 2/2/1 3/3/2   \n"
                     "f -4/-3/-2 -3/-2/-2 -2/-1/-1\n"
                     "s off\n"
                     "f 1 2 5\n" // vertex 5 comes later
                     "v 3 3 3\n"
                     "  f 2 3 4";
  EXPECT_TRUE(acceptsSame(Text));
  ASSERT_FALSE(fast(Text).Declined);
  EXPECT_EQ(fast(Text).Mesh.triangleCount(), 7u);
}

TEST(ObjFast, SameErrorsWhereItAccepts) {
  // Errors found after parsing (indices out of range, no faces, only degenerate faces) come
  // from the code both readers share.
  EXPECT_TRUE(acceptsSame("v 0 0 0\nv 1 0 0\nf 1 2 3\n"));       // vertex index out of range
  EXPECT_TRUE(acceptsSame("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n")); // normal index
  EXPECT_TRUE(acceptsSame("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/2 3/2\nvt 0 0\n")); // texcoord
  EXPECT_TRUE(acceptsSame("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -9 2 3\n")); // before the first
  EXPECT_TRUE(acceptsSame("v 0 0 0\n# nothing else\n"));              // no faces
  EXPECT_TRUE(acceptsSame("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"));  // degenerate only
  EXPECT_NE(fast("v 0 0 0\nv 1 0 0\nf 1 2 3\n").Error.find("vertex index out of range"),
            std::string::npos);
}

TEST(ObjFast, DeclinesWhatItDoesNotRead) {
  const char *Declined[] = {
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", // a quad: tinyobjloader's triangulation
      "v 0 0 0\nv 1 0 0\nf 1 2\n",                       // two corners
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n",            // index 0: the full reader's error
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1/ 2 3\n",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1/1/ 2 3\n",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf +1 2 3\n",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1x 2 3\n",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1234567890 2 3\n",
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1 2\n",     // lines
      "v nan 0 0\n",                                     // the full reader's error
      "v 1e39 0 0\n",
      "v 3.4e38 0 0\n",                                  // near FLT_MAX
      "v 1e1000 0 0\n",                                  // four exponent digits
      "v 0x1p3 0 0\n",
      "v 1 2\n",                                         // too few
      "v 1 2 3 1\n",                                     // w
      "v 1 2 3 0.5 0.5 0.5\n",                           // vertex colours
      "vn 1 2\n",
      "vt 1\n",
      "v 1. 2 3e\n",
      "v . 2 3\n",
      "v 1 2 3 # trailing comment\n",
      "vw 0 1e38 1\n",                                   // tinyobjloader's skin weights
      "vp 0.5\n",
      "# a comment\rv 0 0 0\n",                          // a lone CR ends tinyobjloader's line
      "v 0 0 0\r\r\n",
  };
  for (const char *T : Declined)
    EXPECT_TRUE(fast(T).Declined) << T;
  // A NUL inside a line: the full reader's line ends there.
  EXPECT_TRUE(fast(withNul("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\ng a\0b\n")).Declined);
  EXPECT_TRUE(fast(withNul("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\0\n")).Declined);
  EXPECT_TRUE(fast(withNul("v 0 0\0 0\n")).Declined);
}

// The numbers: tinyobjloader's conversion is not correctly rounded (digit by digit in double,
// then 5^e and 2^e), and the fast reader must give the very same floats. Random decimals of
// every shape the fast reader accepts, one vertex per line.
TEST(ObjFast, NumbersBitForBit) {
  std::mt19937 Rng(26);
  auto Digits = [&](int N) {
    std::string S;
    for (int I = 0; I < N; ++I)
      S += char('0' + Rng() % 10);
    return S;
  };
  for (int Round = 0; Round < 20; ++Round) {
    std::ostringstream Text;
    int Vertices = 0;
    for (int V = 0; V < 300; ++V, ++Vertices) {
      Text << "v";
      for (int C = 0; C < 3; ++C) {
        std::string N;
        switch (Rng() % 4) {
        case 0: N = "-"; break;
        case 1: N = "+"; break;
        default: break;
        }
        int IntDigits = int(Rng() % 8), FracDigits = int(Rng() % 14);
        if (IntDigits == 0 && FracDigits == 0)
          IntDigits = 1;
        N += Digits(IntDigits);
        if (FracDigits > 0 || Rng() % 4 == 0)
          N += "." + Digits(FracDigits);
        if (Rng() % 3 == 0)
          N += std::string(Rng() % 2 ? "e" : "E") + (Rng() % 2 ? "-" : Rng() % 2 ? "+" : "") +
               std::to_string(Rng() % 31); // below 1e38
        Text << (Rng() % 2 ? " " : " \t") << N;
      }
      Text << "\n";
    }
    for (int T = 1; T + 2 <= Vertices; T += 3)
      Text << "f " << T << " " << T + 1 << " " << T + 2 << "\n";
    EXPECT_TRUE(acceptsSame(Text.str())) << "round " << Round;
  }
}

// Whole files of the repository: the fast reader reads every triangulated one, as the full one.
TEST(ObjFast, RepositoryFiles) {
  const fs::path Root = TEXRENDER_SOURCE_DIR;
  int Read = 0;
  for (const char *Dir : {"examples/cornell", "testsuite/Inputs", "fuzz/corpus/obj"}) {
    for (const auto &E : fs::recursive_directory_iterator(Root / Dir)) {
      const std::string Name = E.path().filename().string();
      if (!E.is_regular_file() || Name.find(".obj") == std::string::npos)
        continue;
      const std::string Text = readAll(E.path());
      if (fast(Text).Declined) {
        EXPECT_TRUE(hasPolygonsOrLines(Text)) << E.path();
        continue;
      }
      EXPECT_TRUE(acceptsSame(Text)) << E.path();
      ++Read;
    }
  }
  EXPECT_GE(Read, 12);
}

// Generated normals (faces without vn): the per-position sums visit the faces in the same order.
TEST(ObjFast, GeneratedNormalsSameAsFull) {
  std::ostringstream Text;
  // A bumpy 12 x 12 grid, shared positions, no normals, two triangles a cell.
  const int N = 12;
  for (int Z = 0; Z <= N; ++Z)
    for (int X = 0; X <= N; ++X)
      Text << "v " << X * 0.25 << " " << ((X * 7 + Z * 13) % 5) * 0.03 << " " << Z * 0.25 << "\n";
  for (int Z = 0; Z < N; ++Z)
    for (int X = 0; X < N; ++X) {
      int A = Z * (N + 1) + X + 1, B = A + 1, C = A + N + 1, D = C + 1;
      Text << "f " << A << " " << C << " " << B << "\nf " << B << " " << C << " " << D << "\n";
    }
  EXPECT_TRUE(acceptsSame(Text.str()));
}
