// scene.json, OBJ (plain and gzip) and layout.json loading, and their error messages.
#include "texrender/Error.h"
#include "texrender/Layout.h"
#include "texrender/Scene.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

fs::path tempDir(const std::string &Name) {
  fs::path D = fs::temp_directory_path() / ("texrender-test-" + Name + "-" + std::to_string(::getpid()));
  fs::create_directories(D);
  return D;
}

void writeFile(const fs::path &P, const std::string &Text) { std::ofstream(P) << Text; }

std::string errorOf(const std::function<void()> &F) {
  try {
    F();
  } catch (const Error &E) {
    return E.what();
  }
  return "";
}

const char *Quad = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n";

} // namespace

TEST(Obj, TriangulatesAndGeneratesNormals) {
  fs::path D = tempDir("obj");
  writeFile(D / "quad.obj", Quad);
  TriangleMesh M = loadObj((D / "quad.obj").string());
  ASSERT_EQ(M.triangleCount(), 2u);
  for (auto &N : M.Normals)
    EXPECT_NEAR(std::abs(N[1]), 1.0f, 1e-6);
}

TEST(Obj, ReadsGzip) {
  fs::path D = tempDir("objgz");
  gzFile F = gzopen((D / "quad.obj.gz").c_str(), "wb");
  gzputs(F, Quad);
  gzclose(F);
  EXPECT_EQ(loadObj((D / "quad.obj.gz").string()).triangleCount(), 2u);
}

TEST(Obj, WindingFollowsFileNormals) {
  fs::path D = tempDir("objn");
  writeFile(D / "down.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nvn 0 -1 0\nf 1//1 3//1 2//1\nf 1//1 2//1 3//1\n");
  TriangleMesh M = loadObj((D / "down.obj").string());
  for (size_t T = 0; T < M.triangleCount(); ++T) {
    auto &A = M.Positions[3 * T], &B = M.Positions[3 * T + 1], &C = M.Positions[3 * T + 2];
    float Ny = (C[0] - A[0]) * (B[2] - A[2]) - (B[0] - A[0]) * (C[2] - A[2]);
    EXPECT_LT(Ny, 0.0f) << "triangle " << T;
  }
}

// fuzz/regressions/obj/skin-weight-joint-overflow.obj: tinyobjloader, the reader before
// parseObj, converted a `vw` line's joint id from float to int unchecked (undefined behaviour for
// 1e38); texrender never reads those lines, and line breaks ('\n' or '\r') still count.
TEST(Obj, IgnoresSkinWeightLines) {
  fs::path D = tempDir("objvw");
  writeFile(D / "vw.obj", std::string("vw 0 1e38 1\n  vw\t1 2 3\n") + Quad);
  EXPECT_EQ(loadObj((D / "vw.obj").string()).triangleCount(), 2u);
  writeFile(D / "vwline.obj", "vw 0 1e38 1\rv 0 0 0\nf 0 1 2\n");
  EXPECT_NE(errorOf([&] { loadObj((D / "vwline.obj").string()); }).find("vwline.obj:3: invalid OBJ"),
            std::string::npos);
}

TEST(Obj, MissingFileIsAnError) {
  EXPECT_NE(errorOf([] { loadObj("/nonexistent/x.obj"); }).find("cannot open OBJ file"),
            std::string::npos);
}

TEST(Scene, LoadsAndResolvesPaths) {
  fs::path D = tempDir("scene");
  writeFile(D / "s.json", R"({"texrender": 1, "textures": "out",
    "camera": {"position": [0, 1, 3], "target": [0, 1, 0], "fov": 45},
    "film": {"width": 32, "height": 16}, "render": {"spp": 4, "maxDepth": 3},
    "lights": [{"type": "sky", "radiance": [1, 1, 1]}],
    "meshes": [{"obj": "m.obj", "material": "gray", "transform": {"translate": [1, 2, 3]}}]})");
  Scene S = loadScene((D / "s.json").string());
  EXPECT_EQ(S.Render.Width, 32);
  EXPECT_EQ(S.Render.Spp, 4);
  EXPECT_EQ(S.TexturesDir, (D / "out").string());
  ASSERT_EQ(S.Meshes.size(), 1u);
  EXPECT_EQ(S.Meshes[0].ObjPath, (D / "m.obj").string());
  EXPECT_FLOAT_EQ(S.Meshes[0].Transform[3], 1.0f);
  EXPECT_FLOAT_EQ(S.Meshes[0].Transform[11], 3.0f);
}

TEST(Scene, ErrorsNamePathAndReason) {
  fs::path D = tempDir("scenebad");
  writeFile(D / "a.json", R"({"texrender": 1, "meshes": [{"obj": "m.obj"}]})");
  EXPECT_NE(errorOf([&] { loadScene((D / "a.json").string()); }).find("/meshes/0: a mesh needs \"material\""),
            std::string::npos);
  writeFile(D / "b.json", "{\"texrender\": 1,\n \"camera\": {\"fov\": \"wide\"}}");
  EXPECT_NE(errorOf([&] { loadScene((D / "b.json").string()); }).find("/camera/fov: expected a number"),
            std::string::npos);
  writeFile(D / "c.json", "{\"texrender\": 1,\n  \"meshes\": [}");
  EXPECT_NE(errorOf([&] { loadScene((D / "c.json").string()); }).find("c.json:2:"), std::string::npos);
}
