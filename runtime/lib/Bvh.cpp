#include "texrender/Bvh.h"
#include "texcc/OutOfMemory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace texrender {

namespace {

struct Box {
  Vec3 Lo{INFINITY, INFINITY, INFINITY};
  Vec3 Hi{-INFINITY, -INFINITY, -INFINITY};
  void grow(const Vec3 &P) {
    for (int A = 0; A < 3; ++A)
      Lo[A] = std::min(Lo[A], P[A]), Hi[A] = std::max(Hi[A], P[A]);
  }
  void grow(const Box &B) { grow(B.Lo), grow(B.Hi); }
  float area() const {
    if (Lo[0] > Hi[0])
      return 0;
    float X = Hi[0] - Lo[0], Y = Hi[1] - Lo[1], Z = Hi[2] - Lo[2];
    return 2 * (X * Y + Y * Z + Z * X);
  }
};

struct Builder {
  std::vector<Box> TriBox;
  std::vector<Vec3> Centroid;
  std::vector<uint32_t> &Order;
  std::vector<RtBvhNode> &Nodes;
  unsigned MaxLeaf;
  unsigned Depth = 0;
  static constexpr int Bins = 16;
  static constexpr unsigned MaxDepth = RT_BVH_STACK - 4;

  void setBox(RtBvhNode &N, const Box &B) {
    for (int A = 0; A < 3; ++A)
      N.bmin[A] = B.Lo[A], N.bmax[A] = B.Hi[A];
  }

  /// Finds the best binned-SAH split of [First, First+Count); false when a leaf is cheaper.
  bool findSplit(uint32_t First, uint32_t Count, const Box &NodeBox, int &Axis, float &Pos) {
    Box CB;
    for (uint32_t I = First; I < First + Count; ++I)
      CB.grow(Centroid[Order[I]]);
    float BestCost = INFINITY;
    for (int A = 0; A < 3; ++A) {
      float Lo = CB.Lo[A], Ext = CB.Hi[A] - CB.Lo[A];
      if (Ext <= 0)
        continue;
      Box BinBox[Bins];
      unsigned BinCount[Bins] = {};
      float Scale = Bins / Ext;
      for (uint32_t I = First; I < First + Count; ++I) {
        uint32_t T = Order[I];
        int B = std::min(Bins - 1, int((Centroid[T][A] - Lo) * Scale));
        BinBox[B].grow(TriBox[T]);
        BinCount[B]++;
      }
      float LeftArea[Bins - 1];
      unsigned LeftCount[Bins - 1];
      Box Acc;
      unsigned Cnt = 0;
      for (int B = 0; B < Bins - 1; ++B) {
        Acc.grow(BinBox[B]);
        Cnt += BinCount[B];
        LeftArea[B] = Acc.area();
        LeftCount[B] = Cnt;
      }
      Acc = Box();
      Cnt = 0;
      for (int B = Bins - 1; B > 0; --B) {
        Acc.grow(BinBox[B]);
        Cnt += BinCount[B];
        float Cost = LeftCount[B - 1] * LeftArea[B - 1] + Cnt * Acc.area();
        if (LeftCount[B - 1] > 0 && Cnt > 0 && Cost < BestCost) {
          BestCost = Cost;
          Axis = A;
          Pos = Lo + B / Scale;
        }
      }
    }
    float LeafCost = Count * NodeBox.area();
    return BestCost < LeafCost || (Count > MaxLeaf && BestCost < INFINITY);
  }

  /// Splits at the median along the longest centroid axis (when SAH cannot separate).
  uint32_t medianSplit(uint32_t First, uint32_t Count) {
    Box CB;
    for (uint32_t I = First; I < First + Count; ++I)
      CB.grow(Centroid[Order[I]]);
    int A = 0;
    for (int K = 1; K < 3; ++K)
      if (CB.Hi[K] - CB.Lo[K] > CB.Hi[A] - CB.Lo[A])
        A = K;
    uint32_t Mid = First + Count / 2;
    std::nth_element(Order.begin() + First, Order.begin() + Mid, Order.begin() + First + Count,
                     [&](uint32_t X, uint32_t Y) { return Centroid[X][A] < Centroid[Y][A]; });
    return Mid;
  }

  void build(uint32_t NodeIdx, uint32_t First, uint32_t Count, unsigned Level) {
    Depth = std::max(Depth, Level);
    Box B;
    for (uint32_t I = First; I < First + Count; ++I)
      B.grow(TriBox[Order[I]]);
    setBox(Nodes[NodeIdx], B);
    Nodes[NodeIdx].leftFirst = First;
    Nodes[NodeIdx].count = Count;
    if (Count <= 1)
      return;
    if (Level >= MaxDepth)
      return; // a (large) leaf rather than a traversal-stack overflow
    int Axis = 0;
    float Pos = 0;
    uint32_t Mid;
    if (findSplit(First, Count, B, Axis, Pos)) {
      auto It = std::partition(Order.begin() + First, Order.begin() + First + Count,
                               [&](uint32_t T) { return Centroid[T][Axis] < Pos; });
      Mid = uint32_t(It - Order.begin());
      if (Mid == First || Mid == First + Count)
        Mid = medianSplit(First, Count);
    } else if (Count > MaxLeaf) {
      Mid = medianSplit(First, Count);
    } else {
      return;
    }
    uint32_t Left = uint32_t(Nodes.size());
    Nodes.push_back({});
    Nodes.push_back({});
    Nodes[NodeIdx].leftFirst = Left;
    Nodes[NodeIdx].count = 0;
    build(Left, First, Mid - First, Level + 1);
    build(Left + 1, Mid, First + Count - Mid, Level + 1);
  }
};

Vec3 sub(const Vec3 &A, const Vec3 &B) { return {A[0] - B[0], A[1] - B[1], A[2] - B[2]}; }
Vec3 cross(const Vec3 &A, const Vec3 &B) {
  return {A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
}
float dot(const Vec3 &A, const Vec3 &B) { return A[0] * B[0] + A[1] * B[1] + A[2] * B[2]; }

bool hitBox(const RtBvhNode &N, const Vec3 &O, const Vec3 &InvD, float TMax) {
  float TN = 0, TF = TMax;
  for (int A = 0; A < 3; ++A) {
    float T0 = (N.bmin[A] - O[A]) * InvD[A], T1 = (N.bmax[A] - O[A]) * InvD[A];
    TN = std::max(TN, std::min(T0, T1));
    TF = std::min(TF, std::max(T0, T1));
  }
  return TN <= TF;
}

} // namespace

static Bvh buildBvhSteps(const std::vector<Vec3> &Positions, unsigned MaxLeaf);

Bvh buildBvh(const std::vector<Vec3> &Positions, unsigned MaxLeaf) {
  return texcc::whileAllocating("building the BVH",
                                [&] { return buildBvhSteps(Positions, MaxLeaf); });
}

static Bvh buildBvhSteps(const std::vector<Vec3> &Positions, unsigned MaxLeaf) {
  const auto T0 = std::chrono::steady_clock::now();
  Bvh Out;
  size_t N = Positions.size() / 3;
  Out.Order.resize(N);
  for (size_t I = 0; I < N; ++I)
    Out.Order[I] = uint32_t(I);
  Builder B{{}, {}, Out.Order, Out.Nodes, std::max(1u, MaxLeaf)};
  B.TriBox.resize(N);
  B.Centroid.resize(N);
  for (size_t I = 0; I < N; ++I) {
    for (int C = 0; C < 3; ++C)
      B.TriBox[I].grow(Positions[3 * I + C]);
    for (int A = 0; A < 3; ++A)
      B.Centroid[I][A] = 0.5f * (B.TriBox[I].Lo[A] + B.TriBox[I].Hi[A]);
  }
  Out.Nodes.reserve(2 * N + 1);
  Out.Nodes.push_back({});
  if (N == 0) {
    Out.Nodes[0] = RtBvhNode{{1, 1, 1}, 0, {0, 0, 0}, 0};
    Out.Nodes[0].count = 0;
    return Out;
  }
  B.build(0, 0, uint32_t(N), 0);
  Out.Depth = B.Depth;
  Out.BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - T0).count();
  return Out;
}

float intersectTriangle(const Vec3 &V0, const Vec3 &V1, const Vec3 &V2, const Vec3 &O,
                        const Vec3 &D, float TMin, float TMax) {
  Vec3 E1 = sub(V1, V0), E2 = sub(V2, V0);
  Vec3 P = cross(D, E2);
  float Det = dot(E1, P);
  if (std::fabs(Det) < 1e-20f)
    return -1;
  float Inv = 1.0f / Det;
  Vec3 S = sub(O, V0);
  float U = dot(S, P) * Inv;
  if (U < 0 || U > 1)
    return -1;
  Vec3 Q = cross(S, E1);
  float V = dot(D, Q) * Inv;
  if (V < 0 || U + V > 1)
    return -1;
  float T = dot(E2, Q) * Inv;
  return (T > TMin && T < TMax) ? T : -1;
}

HostHit traceHost(const Bvh &B, const std::vector<Vec3> &P, const Vec3 &O, const Vec3 &D,
                  float TMin, float TMax, bool AnyHit) {
  HostHit H;
  H.T = TMax;
  Vec3 InvD;
  for (int A = 0; A < 3; ++A)
    InvD[A] = 1.0f / (std::fabs(D[A]) > 1e-30f ? D[A] : std::copysign(1e-30f, D[A]));
  std::vector<uint32_t> Stack{0};
  while (!Stack.empty()) {
    const RtBvhNode &N = B.Nodes[Stack.back()];
    Stack.pop_back();
    if (!hitBox(N, O, InvD, H.T))
      continue;
    if (N.count > 0) {
      for (int I = 0; I < N.count; ++I) {
        int T = N.leftFirst + I;
        float Hit = intersectTriangle(P[3 * T], P[3 * T + 1], P[3 * T + 2], O, D, TMin, H.T);
        if (Hit > 0) {
          H.T = Hit, H.Tri = T;
          if (AnyHit)
            return H;
        }
      }
    } else {
      Stack.push_back(N.leftFirst);
      Stack.push_back(N.leftFirst + 1);
    }
  }
  return H;
}

HostHit traceBruteForce(const std::vector<Vec3> &P, const Vec3 &O, const Vec3 &D, float TMin,
                        float TMax) {
  HostHit H;
  H.T = TMax;
  for (size_t T = 0; T < P.size() / 3; ++T) {
    float Hit = intersectTriangle(P[3 * T], P[3 * T + 1], P[3 * T + 2], O, D, TMin, H.T);
    if (Hit > 0)
      H.T = Hit, H.Tri = int(T);
  }
  return H;
}

} // namespace texrender
