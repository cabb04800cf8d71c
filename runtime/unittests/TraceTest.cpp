// The trace backends (Trace.h) on a tiny scene: a primary ray hits the expected triangle (its
// index in BVH order, the id every other stage uses) at the expected t, with the barycentrics of
// v1 and v2 that closest_hit.cl writes; a ray past the triangles misses. Embree and the OpenCL
// traversal must both give it, and a backend shared from another (Trace::share, a lane's)
// gives the owner's hits. Skipped without an OpenCL device.
#include "texrender/Error.h"
#include "texrender/TextureTiers.h"
#include "texrender/Trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <thread>

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

/// A context holding closest-hit rays Rays (origin, direction) over D, in the buffers the
/// backends read: hit i belongs to path Rays.size() - 1 - i.
struct Rig {
  ClContext Cl{0, ""};
  std::map<std::string, cl::Kernel> K;
  std::map<std::string, cl::Buffer> B;
  cl::Buffer Act;
  const SceneData &D;
  size_t N;

  Rig(const SceneData &D, const std::vector<std::pair<Vec3, Vec3>> &Rays) : D(D), N(Rays.size()) {
    std::string Path = kernelDir() + "/closest_hit.cl";
    cl::Program P = Cl.buildProgram(Path, readKernelSource(Path),
                                    "-cl-std=CL1.2 -I " + kernelDir() + "/common");
    K["closest_hit"] = cl::Kernel(P, "closest_hit");
    B["bvhNodes"] = Cl.allocateWith("bvhNodes", D.Tree.Nodes.data(),
                                    D.Tree.Nodes.size() * sizeof(RtBvh4Node), CL_MEM_READ_ONLY);
    B["triangles"] = Cl.allocateWith("triangles", D.Tris.data(), D.Tris.size() * sizeof(RtTri),
                                     CL_MEM_READ_ONLY);
    std::vector<RtPath> Paths(N);
    std::vector<cl_int> Active(N);
    for (size_t I = 0; I < N; ++I) {
      const auto &[O, Dir] = Rays[I];
      Paths[I].origin = {{O[0], O[1], O[2], 0}};
      Paths[I].dir = {{Dir[0], Dir[1], Dir[2], 0}};
      Active[I] = cl_int(N - 1 - I);
    }
    B["paths"] = Cl.allocateWith("paths", Paths.data(), N * sizeof(RtPath), CL_MEM_READ_WRITE);
    Act = Cl.allocateWith("active", Active.data(), N * sizeof(cl_int), CL_MEM_READ_WRITE);
    B["hits"] = Cl.allocate("hits", N * sizeof(RtHit), CL_MEM_READ_WRITE);
  }
  TraceContext context() { return TraceContext{Cl, K, B, D}; }
  /// The closest hits that T (on this context) finds.
  std::vector<RtHit> hits(Trace &T) {
    T.closestHit(Act, int(N), "closest_hit_primary");
    Cl.finish();
    std::vector<RtHit> Hits(N);
    Cl.read(B["hits"], Hits.data(), Hits.size() * sizeof(RtHit));
    return Hits;
  }
};

/// Traces Rays (origin, direction) as closest-hit rays with backend Kind.
std::vector<RtHit> trace(TraceKind Kind, const SceneData &D,
                         const std::vector<std::pair<Vec3, Vec3>> &Rays) {
  Rig R(D, Rays);
  std::unique_ptr<Trace> T = makeTrace(Kind, R.context());
  EXPECT_STREQ(T->name(), traceKindName(Kind));
  std::vector<RtHit> Hits = R.hits(*T);
  EXPECT_EQ(R.Cl.timings().count("closest_hit_primary"), 1u);
  return Hits;
}

/// 3000 random triangles (a BVH several levels deep).
SceneData randomScene(std::mt19937 &Rng) {
  std::uniform_real_distribution<float> U(-1.0f, 1.0f), S(0.02f, 0.15f);
  std::vector<Vec3> In;
  for (int I = 0; I < 3000; ++I) {
    Vec3 C{U(Rng), U(Rng), U(Rng)};
    for (int K = 0; K < 3; ++K)
      In.push_back({C[0] + U(Rng) * S(Rng), C[1] + U(Rng) * S(Rng), C[2] + U(Rng) * S(Rng)});
  }
  return sceneOf(In, 4);
}

std::vector<std::pair<Vec3, Vec3>> randomRays(std::mt19937 &Rng, int N) {
  std::uniform_real_distribution<float> R(-1.5f, 1.5f);
  std::vector<std::pair<Vec3, Vec3>> Rays;
  for (int I = 0; I < N; ++I)
    Rays.push_back({{R(Rng), R(Rng), R(Rng)}, {R(Rng), R(Rng), R(Rng)}});
  return Rays;
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
  SceneData D = randomScene(Rng);
  ASSERT_GT(D.Tree.Depth, 2u);
  std::vector<std::pair<Vec3, Vec3>> Rays = randomRays(Rng, 3000);
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

TEST_P(TraceTest, SharedBackendsTraceTheOwnersSceneAtOnce) {
  // Two backends shared from one (Trace::share, as a frame's lanes share the frame's), each
  // on a context of its own, trace at the same time on two threads after the owner is gone:
  // each finds the owner's hits, bit for bit.
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device";
  std::mt19937 Rng(12);
  SceneData D = randomScene(Rng);
  std::vector<std::pair<Vec3, Vec3>> Rays = randomRays(Rng, 3000);
  Rig Owner(D, Rays), A(D, Rays), B(D, Rays);
  std::unique_ptr<Trace> T = makeTrace(GetParam(), Owner.context());
  const std::vector<RtHit> Expected = Owner.hits(*T);
  std::unique_ptr<Trace> TA = T->share(A.context()), TB = T->share(B.context());
  EXPECT_STREQ(TA->name(), T->name());
  EXPECT_EQ(TA->buildSeconds(), 0.0);
  T.reset();
  std::vector<RtHit> HA, HB;
  std::thread Other([&] { HB = B.hits(*TB); });
  HA = A.hits(*TA);
  Other.join();
  int Hits = 0;
  for (const std::vector<RtHit> *H : {&HA, &HB}) {
    ASSERT_EQ(H->size(), Expected.size());
    for (size_t I = 0; I < Expected.size(); ++I) {
      Hits += Expected[I].tri >= 0;
      EXPECT_EQ((*H)[I].tri, Expected[I].tri) << I;
      EXPECT_EQ(std::memcmp(&(*H)[I], &Expected[I], sizeof(RtHit)), 0) << I;
    }
  }
  EXPECT_GT(Hits, 1000);
}

INSTANTIATE_TEST_SUITE_P(Backends, TraceTest,
                         ::testing::Values(TraceKind::OpenCl, TraceKind::Embree),
                         [](const ::testing::TestParamInfo<TraceKind> &I) {
                           return std::string(traceKindName(I.param));
                         });

} // namespace
