// The host-built BVH against brute force on random triangles (host traversal).
#include "texrender/Bvh.h"

#include <gtest/gtest.h>

#include <random>

using namespace texrender;

namespace {

std::vector<Vec3> randomTriangles(size_t N, unsigned Seed) {
  std::mt19937 Rng(Seed);
  std::uniform_real_distribution<float> U(-1.0f, 1.0f), S(0.01f, 0.2f);
  std::vector<Vec3> P;
  for (size_t I = 0; I < N; ++I) {
    Vec3 C{U(Rng), U(Rng), U(Rng)};
    for (int K = 0; K < 3; ++K)
      P.push_back({C[0] + U(Rng) * S(Rng), C[1] + U(Rng) * S(Rng), C[2] + U(Rng) * S(Rng)});
  }
  return P;
}

std::vector<Vec3> reorder(const Bvh &B, const std::vector<Vec3> &P) {
  std::vector<Vec3> Out(P.size());
  for (size_t K = 0; K < B.Order.size(); ++K)
    for (int C = 0; C < 3; ++C)
      Out[3 * K + C] = P[3 * B.Order[K] + C];
  return Out;
}

} // namespace

TEST(Bvh, OrderIsAPermutationAndLeavesCoverEveryTriangle) {
  auto P = randomTriangles(1000, 1);
  Bvh B = buildBvh(P);
  std::vector<int> Seen(1000, 0);
  for (uint32_t T : B.Order)
    Seen[T]++;
  for (int C : Seen)
    EXPECT_EQ(C, 1);
  size_t InLeaves = 0;
  for (auto &N : B.Nodes)
    if (N.count > 0)
      InLeaves += N.count;
  EXPECT_EQ(InLeaves, 1000u);
  EXPECT_LT(B.Depth, unsigned(RT_BVH_STACK));
}

TEST(Bvh, ClosestHitMatchesBruteForce) {
  auto P = randomTriangles(2000, 2);
  Bvh B = buildBvh(P);
  auto Q = reorder(B, P);
  std::mt19937 Rng(3);
  std::uniform_real_distribution<float> U(-1.5f, 1.5f);
  int Hits = 0;
  for (int I = 0; I < 2000; ++I) {
    Vec3 O{U(Rng), U(Rng), U(Rng)}, D{U(Rng), U(Rng), U(Rng)};
    HostHit A = traceHost(B, Q, O, D, 0.0f, 1e30f, false);
    HostHit Ref = traceBruteForce(Q, O, D, 0.0f, 1e30f);
    ASSERT_EQ(A.Tri, Ref.Tri) << "ray " << I;
    if (Ref.Tri >= 0) {
      EXPECT_FLOAT_EQ(A.T, Ref.T);
      ++Hits;
    }
  }
  EXPECT_GT(Hits, 100);
}

TEST(Bvh, AnyHitAgreesOnOcclusion) {
  auto P = randomTriangles(500, 4);
  Bvh B = buildBvh(P);
  auto Q = reorder(B, P);
  std::mt19937 Rng(5);
  std::uniform_real_distribution<float> U(-1.5f, 1.5f), L(0.1f, 2.0f);
  for (int I = 0; I < 2000; ++I) {
    Vec3 O{U(Rng), U(Rng), U(Rng)}, D{U(Rng), U(Rng), U(Rng)};
    float TMax = L(Rng);
    bool Any = traceHost(B, Q, O, D, 0.0f, TMax, true).Tri >= 0;
    bool Ref = traceBruteForce(Q, O, D, 0.0f, TMax).Tri >= 0;
    ASSERT_EQ(Any, Ref) << "ray " << I;
  }
}

TEST(Bvh, DegenerateInputStaysShallow) {
  // Every triangle at the same place: SAH cannot split, the depth limit must hold.
  std::vector<Vec3> P;
  for (int I = 0; I < 5000; ++I)
    P.insert(P.end(), {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}});
  Bvh B = buildBvh(P);
  EXPECT_LT(B.Depth, unsigned(RT_BVH_STACK));
}
