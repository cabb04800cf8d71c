#ifndef TEXRENDER_UNITTESTS_TESTSCENES_H
#define TEXRENDER_UNITTESTS_TESTSCENES_H

// The scenes of the device tests (DeviceTest.cpp, LanesTest.cpp): OBJ text written to a
// temporary folder, under the hand-written cornell layout ("white" material), and the
// renderer's options for tests (their own program cache, the build's kernels).

#include "texrender/Layout.h"
#include "texrender/Renderer.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace texrender::test {

namespace fs = std::filesystem;

inline std::string sourceDir() {
  if (const char *S = std::getenv("TEXCC_SRC"))
    return S;
  return TEXRENDER_SOURCE_DIR;
}

inline fs::path tempDir(const std::string &Name) {
  fs::path D = fs::temp_directory_path() / ("texrender-dev-" + Name + "-" + std::to_string(::getpid()));
  fs::create_directories(D);
  return D;
}

/// A scene of one or more OBJ files with the hand-written cornell layout ("white" material).
struct TestScene {
  Scene S;
  Layout L;
};

/// Objs (OBJ text each) in Dir, a Size x Size film, 1 spp, the camera above and in front.
inline TestScene makeScene(const fs::path &Dir, const std::vector<std::string> &Objs, int Size) {
  TestScene T;
  T.L = loadLayout(sourceDir() + "/testsuite/Inputs/runtime/cornell-tex");
  T.S.Path = (Dir / "scene.json").string();
  T.S.Cam.Position = {0.0f, 1.5f, 3.0f};
  T.S.Cam.Target = {0.0f, 0.0f, 0.0f};
  T.S.Cam.FovDegrees = 50;
  T.S.Render.Width = T.S.Render.Height = Size;
  T.S.Render.Spp = 1;
  for (size_t I = 0; I < Objs.size(); ++I) {
    fs::path P = Dir / ("m" + std::to_string(I) + ".obj");
    std::ofstream(P) << Objs[I];
    MeshInstance M;
    M.ObjPath = P.string();
    M.Material = "white";
    M.Transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    M.JsonPath = "/meshes/" + std::to_string(I);
    T.S.Meshes.push_back(M);
  }
  return T;
}

inline bool haveDevice() { return !listDevices().empty(); }

inline RendererOptions testOptions() {
  RendererOptions O;
  O.CacheDir = (fs::temp_directory_path() / "texrender-test-cache").string();
  if (!std::getenv("TEXRENDER_KERNELS"))
    O.KernelDir = TEXRENDER_KERNEL_DIR;
  return O;
}

/// A 4 x 4 floor at y = 0 and a 0.8 cube standing on it.
inline const char *FloorAndCube =
    "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\nvn 0 1 0\nf 1//1 4//1 3//1 2//1\n"
    "v -0.4 0 -0.4\nv 0.4 0 -0.4\nv 0.4 0 0.4\nv -0.4 0 0.4\n"
    "v -0.4 0.8 -0.4\nv 0.4 0.8 -0.4\nv 0.4 0.8 0.4\nv -0.4 0.8 0.4\n"
    "f 9 10 11 12\nf 5 6 10 9\nf 6 7 11 10\nf 7 8 12 11\nf 8 5 9 12\n";

} // namespace texrender::test

#endif
