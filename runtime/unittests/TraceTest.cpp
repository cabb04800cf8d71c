// The trace backends (Trace.h) on a tiny scene: a primary ray hits the expected triangle (its
// index in BVH order, the id every other stage uses) at the expected t, with the barycentrics of
// v1 and v2 that closest_hit.cl writes; a ray past the triangles misses. Embree and the OpenCL
// traversal must both give it. Skipped without an OpenCL device.
#include "texrender/Error.h"
#include "texrender/TextureTiers.h"
#include "texrender/Trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

std::string kernelDir() {
  if (const char *E = std::getenv("TEXRENDER_KERNELS"))
    return E;
  return TEXRENDER_KERNEL_DIR;
}

/// The scene data of triangles In (3 vertices each), in BVH order.
SceneData sceneOf(const std::vector<Vec3> &In, unsigned MaxLeaf) {
  SceneData D;
  D.Tree = buildBvh(In, MaxLeaf);
  for (uint32_t T : D.Tree.Order) {
    const Vec3 &A = In[3 * T], &B = In[3 * T + 1], &C = In[3 * T + 2];
    D.Positions.insert(D.Positions.end(), {A, B, C});
    D.Tris.push_back({{{A[0], A[1], A[2], 0}},
                      {{B[0] - A[0], B[1] - A[1], B[2] - A[2], 0}},
                      {{C[0] - A[0], C[1] - A[1], C[2] - A[2], 0}}});
  }
  return D;
}

/// Two triangles facing +z: A in the plane z = -2 (x, y in [0, 1]), B in z = -5 (x, y in
/// [-1, 0]); both as (v0, v1, v2) = (origin, +x, +y) of their square's corner.
SceneData tinyScene() {
  return sceneOf({{0, 0, -2}, {1, 0, -2}, {0, 1, -2}, {-1, -1, -5}, {0, -1, -5}, {-1, 0, -5}}, 1);
}

/// Traces Rays (origin, direction) as closest-hit rays with backend Kind.
std::vector<RtHit> trace(TraceKind Kind, const SceneData &D,
                         const std::vector<std::pair<Vec3, Vec3>> &Rays) {
  ClContext Cl(0, "");
  std::map<std::string, cl::Kernel> K;
  std::map<std::string, cl::Buffer> B;
  std::string Path = kernelDir() + "/closest_hit.cl";
  cl::Program P = Cl.buildProgram(Path, readKernelSource(Path),
                                  "-cl-std=CL1.2 -I " + kernelDir() + "/common");
  K["closest_hit"] = cl::Kernel(P, "closest_hit");
  B["bvhNodes"] = Cl.allocateWith("bvhNodes", D.Tree.Nodes.data(),
                                  D.Tree.Nodes.size() * sizeof(RtBvh4Node), CL_MEM_READ_ONLY);
  B["triangles"] = Cl.allocateWith("triangles", D.Tris.data(), D.Tris.size() * sizeof(RtTri),
                                   CL_MEM_READ_ONLY);
  std::vector<RtPath> Paths(Rays.size());
  std::vector<cl_int> Active(Rays.size());
  for (size_t I = 0; I < Rays.size(); ++I) {
    const auto &[O, Dir] = Rays[I];
    Paths[I].origin = {{O[0], O[1], O[2], 0}};
    Paths[I].dir = {{Dir[0], Dir[1], Dir[2], 0}};
    Active[I] = cl_int(Rays.size() - 1 - I); // hit i belongs to path active[i]
  }
  B["paths"] = Cl.allocateWith("paths", Paths.data(), Paths.size() * sizeof(RtPath),
                               CL_MEM_READ_WRITE);
  cl::Buffer Act = Cl.allocateWith("active", Active.data(), Active.size() * sizeof(cl_int),
                                   CL_MEM_READ_WRITE);
  B["hits"] = Cl.allocate("hits", Rays.size() * sizeof(RtHit), CL_MEM_READ_WRITE);
  std::unique_ptr<Trace> T = makeTrace(Kind, TraceContext{Cl, K, B, D});
  EXPECT_STREQ(T->name(), traceKindName(Kind));
  T->closestHit(Act, int(Rays.size()), "closest_hit_primary");
  Cl.finish();
  std::vector<RtHit> Hits(Rays.size());
  Cl.read(B["hits"], Hits.data(), Hits.size() * sizeof(RtHit));
  EXPECT_EQ(Cl.timings().count("closest_hit_primary"), 1u);
  return Hits;
}

class TraceTest : public ::testing::TestWithParam<TraceKind> {};

TEST_P(TraceTest, PrimaryRayHitsExpectedTriangle) {
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  SceneData D = tinyScene();
  // Position in BVH order of each input triangle.
  int PosOf[2];
  for (size_t K = 0; K < D.Tree.Order.size(); ++K)
    PosOf[D.Tree.Order[K]] = int(K);
  // Path 0 (hit 2): through A at (0.25, 0.5): u = 0.25 (v1 = +x), v = 0.5 (v2 = +y), t = 2.
  // Path 1 (hit 1): through B at (-0.9, -0.8): u = 0.1, v = 0.2, t = 5 (A is not in the way).
  // Path 2 (hit 0): misses both.
  std::vector<std::pair<Vec3, Vec3>> Rays = {
      {{0.25f, 0.5f, 0}, {0, 0, -1}}, {{-0.9f, -0.8f, 0}, {0, 0, -1}}, {{3, 3, 0}, {0, 0, -1}}};
  std::vector<RtHit> H = trace(GetParam(), D, Rays);
  EXPECT_EQ(H[2].tri, PosOf[0]);
  EXPECT_NEAR(H[2].t, 2.0f, 1e-5f);
  EXPECT_NEAR(H[2].u, 0.25f, 1e-5f);
  EXPECT_NEAR(H[2].v, 0.5f, 1e-5f);
  EXPECT_EQ(H[1].tri, PosOf[1]);
  EXPECT_NEAR(H[1].t, 5.0f, 1e-5f);
  EXPECT_NEAR(H[1].u, 0.1f, 1e-5f);
  EXPECT_NEAR(H[1].v, 0.2f, 1e-5f);
  EXPECT_EQ(H[0].tri, -1);
  EXPECT_TRUE(std::isinf(H[0].t));
}

TEST_P(TraceTest, ClosestHitsMatchBruteForce) {
  // 3000 random triangles (a BVH several levels deep) and 3000 random rays: the backend's
  // closest hit is brute force's triangle at its t.
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  std::mt19937 Rng(11);
  std::uniform_real_distribution<float> U(-1.0f, 1.0f), S(0.02f, 0.15f), R(-1.5f, 1.5f);
  std::vector<Vec3> In;
  for (int I = 0; I < 3000; ++I) {
    Vec3 C{U(Rng), U(Rng), U(Rng)};
    for (int K = 0; K < 3; ++K)
      In.push_back({C[0] + U(Rng) * S(Rng), C[1] + U(Rng) * S(Rng), C[2] + U(Rng) * S(Rng)});
  }
  SceneData D = sceneOf(In, 4);
  ASSERT_GT(D.Tree.Depth, 2u);
  std::vector<std::pair<Vec3, Vec3>> Rays;
  for (int I = 0; I < 3000; ++I)
    Rays.push_back({{R(Rng), R(Rng), R(Rng)}, {R(Rng), R(Rng), R(Rng)}});
  std::vector<RtHit> H = trace(GetParam(), D, Rays);
  int Hits = 0, Mismatches = 0;
  for (size_t I = 0; I < Rays.size(); ++I) {
    // Hit i belongs to path Rays.size() - 1 - i (trace()'s active list).
    const auto &[O, Dir] = Rays[Rays.size() - 1 - I];
    HostHit Ref = traceBruteForce(D.Positions, O, Dir, 0.0f, INFINITY);
    if (Ref.Tri < 0) {
      Mismatches += H[I].tri != -1;
      continue;
    }
    ++Hits;
    // Embree's triangle test differs from Moeller-Trumbore in the last bits: a ray through a
    // shared edge may take the neighbour, at the same t.
    if (H[I].tri != Ref.Tri && std::fabs(H[I].t - Ref.T) > 1e-5f * Ref.T)
      ++Mismatches;
  }
  EXPECT_GT(Hits, 500);
  EXPECT_EQ(Mismatches, 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, TraceTest,
                         ::testing::Values(TraceKind::OpenCl, TraceKind::Embree),
                         [](const ::testing::TestParamInfo<TraceKind> &I) {
                           return std::string(traceKindName(I.param));
                         });

} // namespace
