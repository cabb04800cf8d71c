// The wide BVH (Embree's builder, RtBvh4Node) against brute force on random triangles (host
// traversal, the device's algorithm), and its structure: every triangle in exactly one leaf,
// every child's box holding its subtree, the depth within the device stack.
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
  // Every leaf slot's range, once each, covers [0, 1000); every inner child is referenced once.
  std::vector<int> InLeaf(1000, 0), Parents(B.Nodes.size(), 0);
  for (auto &N : B.Nodes)
    for (int K = 0; K < 4; ++K) {
      if (N.lox.s[K] > N.hix.s[K])
        continue; // an unused slot
      int32_t R = N.child.s[K];
      if (R >= 0) {
        ASSERT_LT(size_t(R), B.Nodes.size());
        Parents[size_t(R)]++;
        continue;
      }
      uint32_t V = ~uint32_t(R);
      uint32_t First = V >> RT_BVH_LEAF_BITS, Count = V & ((1u << RT_BVH_LEAF_BITS) - 1);
      EXPECT_GE(Count, 1u);
      EXPECT_LE(Count, 4u);
      for (uint32_t T = First; T < First + Count; ++T) {
        ASSERT_LT(T, 1000u);
        InLeaf[T]++;
        // The slot's box holds the triangle.
        for (int C = 0; C < 3; ++C) {
          const Vec3 &V3 = P[3 * B.Order[T] + C];
          EXPECT_GE(V3[0], N.lox.s[K]);
          EXPECT_LE(V3[0], N.hix.s[K]);
          EXPECT_GE(V3[1], N.loy.s[K]);
          EXPECT_LE(V3[1], N.hiy.s[K]);
          EXPECT_GE(V3[2], N.loz.s[K]);
          EXPECT_LE(V3[2], N.hiz.s[K]);
        }
      }
    }
  for (int C : InLeaf)
    EXPECT_EQ(C, 1);
  EXPECT_EQ(Parents[0], 0);
  for (size_t I = 1; I < Parents.size(); ++I)
    EXPECT_EQ(Parents[I], 1) << "node " << I;
  EXPECT_GT(B.Depth, 0u);
  EXPECT_LT(B.Depth, unsigned(RT_BVH_MAX_DEPTH));
  EXPECT_GT(B.BuildSeconds, 0.0);
}

TEST(Bvh, IsWide) {
  // Four children a node: a binary tree over 4096 triangles would need about 2 * 4096 / 4
  // nodes; a 4-wide one about a third of that.
  auto P = randomTriangles(4096, 6);
  Bvh B = buildBvh(P);
  size_t Slots = 0;
  for (auto &N : B.Nodes)
    for (int K = 0; K < 4; ++K)
      Slots += N.lox.s[K] <= N.hix.s[K];
  EXPECT_GT(double(Slots) / double(B.Nodes.size()), 3.0);
}

TEST(Bvh, EmptyAndSingleTriangle) {
  Bvh E = buildBvh({});
  ASSERT_EQ(E.Nodes.size(), 1u);
  EXPECT_EQ(traceHost(E, {}, {0, 0, 0}, {0, 0, 1}, 0.0f, 1e30f, false).Tri, -1);
  std::vector<Vec3> One = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  Bvh B = buildBvh(One);
  ASSERT_EQ(B.Order.size(), 1u);
  HostHit H = traceHost(B, One, {0.2f, 0.2f, 0}, {0, 0, 1}, 0.0f, 1e30f, false);
  EXPECT_EQ(H.Tri, 0);
  EXPECT_FLOAT_EQ(H.T, 1.0f);
  EXPECT_EQ(traceHost(B, One, {2, 2, 0}, {0, 0, 1}, 0.0f, 1e30f, false).Tri, -1);
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
  EXPECT_LT(B.Depth, unsigned(RT_BVH_MAX_DEPTH));
  EXPECT_EQ(B.Order.size(), 5000u);
  auto Q = reorder(B, P);
  HostHit H = traceHost(B, Q, {0.2f, 0.2f, -1}, {0, 0, 1}, 0.0f, 1e30f, false);
  EXPECT_GE(H.Tri, 0);
  EXPECT_FLOAT_EQ(H.T, 1.0f);
}
