// The OBJ reader (ObjLoader.cpp, parseObj): what it reads must be what tinyobjloader, the reader
// before it, read, bit for bit (numbers, indices, quads: meshes and images stay the same), and
// its errors must name the line.
#include "texrender/Error.h"
#include "texrender/Scene.h"

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

/// What tinyobjloader (the reader before parseObj, kept as the tests' oracle) reads from Text:
/// its arrays and its triangulated corners (texrender's settings: triangulate, no colours).
struct Oracle {
  bool Ok = false;
  ObjText Obj;
};

Oracle viaTinyObj(const std::string &Text) {
  tinyobj::ObjReaderConfig Cfg;
  Cfg.triangulate = true;
  Cfg.vertex_color = false;
  tinyobj::ObjReader R;
  Oracle O;
  O.Ok = R.ParseFromString(Text, "", Cfg);
  if (!O.Ok)
    return O;
  const tinyobj::attrib_t &A = R.GetAttrib();
  O.Obj.Positions = A.vertices, O.Obj.Normals = A.normals, O.Obj.TexCoords = A.texcoords;
  for (const tinyobj::shape_t &S : R.GetShapes())
    for (const tinyobj::index_t &I : S.mesh.indices) {
      ObjCorner C;
      C.V = I.vertex_index, C.T = I.texcoord_index, C.N = I.normal_index;
      O.Obj.Corners.push_back(C);
    }
  return O;
}

/// parseObj's result, or its error message in Error.
struct Parsed {
  std::string Error;
  ObjText Obj;
};

Parsed parse(const std::string &Text) {
  Parsed P;
  try {
    P.Obj = parseObj("t.obj", Text);
  } catch (const texrender::Error &E) {
    P.Error = E.what();
  }
  return P;
}

template <typename T> bool sameBits(const std::vector<T> &A, const std::vector<T> &B) {
  return A.size() == B.size() && (A.empty() || std::memcmp(A.data(), B.data(), A.size() * sizeof(T)) == 0);
}

/// parseObj reads Text without error and gives tinyobjloader's arrays and corners, bit for bit.
::testing::AssertionResult sameAsTinyObj(const std::string &Text) {
  Parsed P = parse(Text);
  Oracle O = viaTinyObj(Text);
  if (!P.Error.empty() || !O.Ok)
    return ::testing::AssertionFailure() << "error '" << P.Error << "' / tinyobjloader "
                                         << (O.Ok ? "read it" : "failed") << ":\n" << Text;
  if (!sameBits(P.Obj.Positions, O.Obj.Positions) || !sameBits(P.Obj.Normals, O.Obj.Normals) ||
      !sameBits(P.Obj.TexCoords, O.Obj.TexCoords))
    return ::testing::AssertionFailure() << "arrays differ:\n" << Text;
  if (P.Obj.Corners.size() != O.Obj.Corners.size())
    return ::testing::AssertionFailure() << P.Obj.Corners.size() << " corners against "
                                         << O.Obj.Corners.size() << ":\n" << Text;
  for (size_t K = 0; K < P.Obj.Corners.size(); ++K) {
    const ObjCorner &A = P.Obj.Corners[K], &B = O.Obj.Corners[K];
    if (A.V != B.V || A.T != B.T || A.N != B.N)
      return ::testing::AssertionFailure() << "corner " << K << " differs:\n" << Text;
  }
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

/// Whether Text has a polygon of five or more corners (tinyobjloader clips ears, parseObj fans).
bool hasLargePolygons(const std::string &Text) {
  std::istringstream In(Text);
  for (std::string Line; std::getline(In, Line);) {
    std::istringstream Words(Line);
    std::string First, W;
    Words >> First;
    int Count = 0;
    while (Words >> W)
      ++Count;
    if (First == "f" && Count > 4)
      return true;
  }
  return false;
}

} // namespace

TEST(ObjReader, SameAsTinyObj) {
  // Every statement: comments, blank lines, CRLF, a lone CR, tabs, groups, objects, smoothing
  // groups, materials, lines, points, skin weights, parameter-space vertices (all ignored), the
  // four corner forms, negative and forward indices, a '+', signs, leading and trailing dots,
  // exponents, a comment after numbers, a missing coordinate, vt with one and three numbers,
  // faces of one and two corners (skipped), quads split either way.
  const char *Text = "# a comment\r\n"
                     "mtllib none.mtl\n"
                     "o first\n"
                     "\n"
                     "   \t\n"
                     "v 0 0 0\n"
                     "v\t1.5 -0 .25\r\n"
                     "v +2. 1e-2 -3.5E+1\n"
                     "v 0.12345678901 1.000000001 7e3 # a comment\n"
                     "vt 0 0\n"
                     "vt 1 0 0\n"
                     "vt .5\n"
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
                     "# old Mac line end\rv 5 5\n"
                     "l 1 2\n"
                     "p 3\n"
                     "vw 0 0 0.25 1 0.75\n"
                     "vp 0.5 0.5\n"
                     "f 1\n"
                     "f 1 2\n"
                     "s off\n"
                     "f 1 2 6\n" // vertex 6 comes later
                     "v 3 3 3\n"
                     "v 0 0 1\n"
                     "v 0.9 0 0.9\n"
                     "v 1 0 0\n"
                     "f 1 +7 8 9\n"   // a quad, diagonal 0-2 shorter
                     "f 1 9 8 7\n"    // the same quad from another corner
                     "v 0 0 0.01\nv 1 0 0\nv 1.2 0 1\nv 0 0 1\n"
                     "f -4 -3 -2 -1\n" // the other diagonal shorter
                     "  f 2 3 4";
  EXPECT_TRUE(sameAsTinyObj(Text));
  EXPECT_EQ(parse(Text).Obj.Corners.size(), 3u * 13u);
}

TEST(ObjReader, ErrorsNameTheLine) {
  EXPECT_EQ(parse("v 0 0 0\nv nan 0 0\n").Error, "t.obj:2: invalid OBJ: 'nan' is not a finite number");
  EXPECT_EQ(parse("v 0 0 0\n\nv 0 1e39 0\n").Error,
            "t.obj:3: invalid OBJ: '1e39' is not a finite number");
  EXPECT_EQ(parse("vn 0 0 0e999\n").Error, "t.obj:1: invalid OBJ: '0e999' is not a finite number");
  EXPECT_EQ(parse("vt 0x1p3 0\n").Error, "t.obj:1: invalid OBJ: '0x1p3' is not a finite number");
  EXPECT_EQ(parse("v 1 2 3 4x\n").Error, "t.obj:1: invalid OBJ: '4x' is not a finite number");
  EXPECT_EQ(parse(withNul("v 0 0\0 0\n")).Error,
            "t.obj:1: invalid OBJ: '0\\x00' is not a finite number");
  const std::string Corner = "' is not v, v/t, v//n or v/t/n with non-zero indices";
  EXPECT_EQ(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\r\nf 0 1 2\n").Error,
            "t.obj:4: invalid OBJ: face corner '0" + Corner);
  EXPECT_EQ(parse("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1/ 2 3\r").Error,
            "t.obj:4: invalid OBJ: face corner '1/" + Corner);
  EXPECT_EQ(parse("f 1 2 3/4/5/6\n").Error, "t.obj:1: invalid OBJ: face corner '3/4/5/6" + Corner);
  EXPECT_EQ(parse("f 1 2a 3\n").Error, "t.obj:1: invalid OBJ: face corner '2a" + Corner);
  EXPECT_EQ(parse("f 1 2 1234567890\n").Error,
            "t.obj:1: invalid OBJ: face corner '1234567890" + Corner);
}

// Polygons of five or more corners are fanned from the first (tinyobjloader clipped ears).
TEST(ObjReader, LargePolygonsFanned) {
  Parsed P = parse("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n");
  ASSERT_EQ(P.Error, "");
  const int Want[] = {0, 1, 2, 0, 2, 3, 0, 3, 4};
  ASSERT_EQ(P.Obj.Corners.size(), 9u);
  for (int K = 0; K < 9; ++K)
    EXPECT_EQ(P.Obj.Corners[size_t(K)].V, Want[K]) << K;
}

// The numbers: tinyobjloader's conversion is not correctly rounded (digit by digit in double,
// then 5^e and 2^e), and parseObj must give the very same floats (or the images would move).
// Random decimals of every shape, one vertex per line.
TEST(ObjReader, NumbersBitForBit) {
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
    EXPECT_TRUE(sameAsTinyObj(Text.str())) << "round " << Round;
  }
}

// Whole files: the repository's OBJs and, where ../shared/assets is beside the repository, the
// shared assets (teapot, bunny, Cornell box, Sponza, Suzanne; gzip): as tinyobjloader read them.
TEST(ObjReader, RepositoryAndAssetFiles) {
  const fs::path Root = TEXRENDER_SOURCE_DIR;
  int Read = 0;
  for (const fs::path &Dir : {Root / "examples/cornell", Root / "testsuite/Inputs",
                             Root / "fuzz/corpus/obj", Root / "fuzz/regressions/obj",
                             Root.parent_path() / "shared/assets"}) {
    if (!fs::exists(Dir))
      continue;
    for (const auto &E : fs::recursive_directory_iterator(Dir)) {
      const std::string Name = E.path().filename().string();
      if (!E.is_regular_file() || Name.find(".obj") == std::string::npos ||
          E.file_size() > (64u << 20))
        continue;
      std::string Text = readAll(E.path());
      if (Name == "skin-weight-joint-overflow.obj") { // tinyobjloader's undefined behaviour
        EXPECT_EQ(parse(Text).Error, "") << E.path();
        continue;
      }
      if (hasLargePolygons(Text)) {
        Parsed P = parse(Text);
        Oracle O = viaTinyObj(Text);
        EXPECT_TRUE(P.Error.empty() && O.Ok && sameBits(P.Obj.Positions, O.Obj.Positions) &&
                    sameBits(P.Obj.Normals, O.Obj.Normals) &&
                    sameBits(P.Obj.TexCoords, O.Obj.TexCoords))
            << E.path();
      } else {
        EXPECT_TRUE(sameAsTinyObj(Text)) << E.path();
      }
      ++Read;
    }
  }
  EXPECT_GE(Read, 15);
}
