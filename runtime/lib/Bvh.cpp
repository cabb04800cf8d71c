#include "texrender/Bvh.h"
#include "texrender/Error.h"
#include "texrender/Threads.h"
#include "texcc/OutOfMemory.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <new>
#include <string>
#include <utility>

namespace texrender {

namespace {

// The builder's own nodes (allocated by Embree's thread-local allocator, freed with the
// RTCBVH), flattened into RtBvh4Node once the build is done. Kind comes first in both.
struct TmpInner {
  uint32_t Kind = 0;
  unsigned N = 0;
  void *Child[4] = {};
  RTCBounds Box[4] = {};
};
struct TmpLeaf {
  uint32_t Kind = 1;
  unsigned N = 0;
  unsigned Prim[RT_BVH_MAX_LEAF] = {};
};

void *createNode(RTCThreadLocalAllocator A, unsigned Count, void *) {
  void *M = rtcThreadLocalAlloc(A, sizeof(TmpInner), 16);
  auto *N = new (M) TmpInner;
  N->N = std::min(Count, 4u);
  return N;
}

void setNodeChildren(void *Node, void **Children, unsigned Count, void *) {
  auto *N = static_cast<TmpInner *>(Node);
  for (unsigned I = 0; I < Count && I < 4; ++I)
    N->Child[I] = Children[I];
}

void setNodeBounds(void *Node, const RTCBounds **Bounds, unsigned Count, void *) {
  auto *N = static_cast<TmpInner *>(Node);
  for (unsigned I = 0; I < Count && I < 4; ++I)
    N->Box[I] = *Bounds[I];
}

void *createLeaf(RTCThreadLocalAllocator A, const RTCBuildPrimitive *Prims, size_t Count,
                 void *) {
  void *M = rtcThreadLocalAlloc(A, sizeof(TmpLeaf), 16);
  auto *L = new (M) TmpLeaf;
  L->N = unsigned(std::min<size_t>(Count, RT_BVH_MAX_LEAF)); // maxLeafSize keeps Count within
  for (unsigned I = 0; I < L->N; ++I)
    L->Prim[I] = Prims[I].primID;
  return L;
}

void embreeError(void *User, RTCError Code, const char *Message) {
  auto *Last = static_cast<std::string *>(User);
  try {
    if (Last->empty())
      *Last = std::string(Message ? Message : "") + " (Embree error " + std::to_string(int(Code)) + ")";
  } catch (const std::bad_alloc &) {
    // Out of memory: the caller reads the code from rtcGetDeviceError.
  }
}

RtBvh4Node emptyNode() {
  RtBvh4Node N;
  for (int K = 0; K < 4; ++K) {
    N.lox.s[K] = N.loy.s[K] = N.loz.s[K] = FLT_MAX;
    N.hix.s[K] = N.hiy.s[K] = N.hiz.s[K] = -FLT_MAX;
    N.child.s[K] = 0;
    N.pad.s[K] = 0;
  }
  return N;
}

void setLane(RtBvh4Node &N, int K, const RTCBounds &B) {
  N.lox.s[K] = B.lower_x, N.loy.s[K] = B.lower_y, N.loz.s[K] = B.lower_z;
  N.hix.s[K] = B.upper_x, N.hiy.s[K] = B.upper_y, N.hiz.s[K] = B.upper_z;
}

/// Flattens the builder's tree depth first: an inner node's index is its position in Nodes,
/// a leaf's triangles are appended to Order.
struct Flattener {
  Bvh &Out;

  int32_t ref(const void *P, unsigned Level) {
    if (*static_cast<const uint32_t *>(P) == 1) {
      const auto &L = *static_cast<const TmpLeaf *>(P);
      size_t First = Out.Order.size();
      if (First >= (size_t(1) << (31 - RT_BVH_LEAF_BITS)))
        throw Error("too many triangles for the BVH's leaf references: " + std::to_string(First));
      Out.Order.insert(Out.Order.end(), L.Prim, L.Prim + L.N);
      return ~int32_t((First << RT_BVH_LEAF_BITS) | L.N);
    }
    size_t Idx = Out.Nodes.size();
    Out.Nodes.push_back(emptyNode());
    fill(Idx, *static_cast<const TmpInner *>(P), Level);
    return int32_t(Idx);
  }

  void fill(size_t Idx, const TmpInner &In, unsigned Level) {
    Out.Depth = std::max(Out.Depth, Level);
    RtBvh4Node N = emptyNode();
    for (unsigned K = 0; K < In.N; ++K) {
      setLane(N, int(K), In.Box[K]);
      N.child.s[K] = ref(In.Child[K], Level + 1);
    }
    Out.Nodes[Idx] = N;
  }
};

/// An Embree device and BVH for one build (released by the destructor).
struct Builder {
  RTCDevice Device = nullptr;
  RTCBVH Tree = nullptr;
  std::string LastError;
  ~Builder() {
    if (Tree)
      rtcReleaseBVH(Tree);
    if (Device)
      rtcReleaseDevice(Device);
  }
  void check(const char *What) {
    if (Device && rtcGetDeviceError(Device) == RTC_ERROR_OUT_OF_MEMORY)
      throw std::bad_alloc(); // named by buildBvh's step
    if (!LastError.empty())
      throw Error(std::string(What) + ": " + LastError);
  }
};

Vec3 sub(const Vec3 &A, const Vec3 &B) { return {A[0] - B[0], A[1] - B[1], A[2] - B[2]}; }
Vec3 cross(const Vec3 &A, const Vec3 &B) {
  return {A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
}
float dot(const Vec3 &A, const Vec3 &B) { return A[0] * B[0] + A[1] * B[1] + A[2] * B[2]; }

} // namespace

static Bvh buildBvhSteps(const std::vector<Vec3> &Positions, unsigned MaxLeaf);

Bvh buildBvh(const std::vector<Vec3> &Positions, unsigned MaxLeaf) {
  return texcc::whileAllocating("building the BVH",
                                [&] { return buildBvhSteps(Positions, MaxLeaf); });
}

static Bvh buildBvhSteps(const std::vector<Vec3> &Positions, unsigned MaxLeaf) {
  const auto T0 = std::chrono::steady_clock::now();
  Bvh Out;
  const size_t N = Positions.size() / 3;
  Out.Nodes.push_back(emptyNode()); // the root; all slots empty for an empty scene
  if (N > 0) {
    std::vector<RTCBuildPrimitive> Prims(N);
    RTCBounds All{FLT_MAX, FLT_MAX, FLT_MAX, 0, -FLT_MAX, -FLT_MAX, -FLT_MAX, 0};
    for (size_t I = 0; I < N; ++I) {
      RTCBuildPrimitive &P = Prims[I];
      P.lower_x = P.lower_y = P.lower_z = FLT_MAX;
      P.upper_x = P.upper_y = P.upper_z = -FLT_MAX;
      for (int C = 0; C < 3; ++C) {
        const Vec3 &V = Positions[3 * I + C];
        P.lower_x = std::min(P.lower_x, V[0]), P.upper_x = std::max(P.upper_x, V[0]);
        P.lower_y = std::min(P.lower_y, V[1]), P.upper_y = std::max(P.upper_y, V[1]);
        P.lower_z = std::min(P.lower_z, V[2]), P.upper_z = std::max(P.upper_z, V[2]);
      }
      P.geomID = 0;
      P.primID = unsigned(I);
      All.lower_x = std::min(All.lower_x, P.lower_x), All.upper_x = std::max(All.upper_x, P.upper_x);
      All.lower_y = std::min(All.lower_y, P.lower_y), All.upper_y = std::max(All.upper_y, P.upper_y);
      All.lower_z = std::min(All.lower_z, P.lower_z), All.upper_z = std::max(All.upper_z, P.upper_z);
    }
    Builder B;
    B.Device = rtcNewDevice(embreeDeviceConfig().c_str()); // renderThreads() threads
    if (!B.Device && rtcGetDeviceError(nullptr) == RTC_ERROR_OUT_OF_MEMORY)
      throw std::bad_alloc(); // named by buildBvh's step (Embree's threads did not start)
    if (!B.Device)
      throw Error("cannot start Embree to build the BVH: " +
                  std::to_string(int(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(B.Device, embreeError, &B.LastError);
    B.Tree = rtcNewBVH(B.Device);
    B.check("cannot create the BVH");
    RTCBuildArguments A = rtcDefaultBuildArguments();
    A.byteSize = sizeof(A);
    // Binned SAH (no spatial splits: every triangle is in exactly one leaf, so that the
    // reordered triangle array has the scene's triangle ids).
    A.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    A.maxBranchingFactor = 4;
    A.maxDepth = RT_BVH_MAX_DEPTH;
    A.sahBlockSize = 1;
    A.minLeafSize = 1;
    A.maxLeafSize = std::clamp(MaxLeaf, 1u, unsigned(RT_BVH_MAX_LEAF));
    A.traversalCost = 1.0f;
    A.intersectionCost = 1.0f;
    A.bvh = B.Tree;
    A.primitives = Prims.data();
    A.primitiveCount = N;
    A.primitiveArrayCapacity = N;
    A.createNode = createNode;
    A.setNodeChildren = setNodeChildren;
    A.setNodeBounds = setNodeBounds;
    A.createLeaf = createLeaf;
    void *Root = rtcBuildBVH(&A);
    B.check("cannot build the BVH");
    if (!Root)
      throw Error("cannot build the BVH: Embree's builder returned no tree");
    Out.Order.reserve(N);
    Flattener F{Out};
    if (*static_cast<const uint32_t *>(Root) == 1) { // a single leaf: the root's only child
      setLane(Out.Nodes[0], 0, All);
      Out.Nodes[0].child.s[0] = F.ref(Root, 1);
    } else {
      F.fill(0, *static_cast<const TmpInner *>(Root), 0);
    }
    if (Out.Order.size() != N)
      throw Error("the BVH's leaves hold " + std::to_string(Out.Order.size()) + " of " +
                  std::to_string(N) + " triangles");
  }
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
  // Nearest first, as rt_trace: the closest child is visited next, the others are stacked.
  std::vector<std::pair<int32_t, float>> Stack;
  int32_t Ref = 0;
  while (true) {
    if (Ref >= 0) {
      const RtBvh4Node &N = B.Nodes[size_t(Ref)];
      const cl_float4 *Lo[3] = {&N.lox, &N.loy, &N.loz}, *Hi[3] = {&N.hix, &N.hiy, &N.hiz};
      std::pair<int32_t, float> Hit[4];
      int M = 0;
      for (int K = 0; K < 4; ++K) {
        float TN = 0, TF = H.T;
        for (int A = 0; A < 3; ++A) {
          float Near = (InvD[A] < 0 ? Hi : Lo)[A]->s[K], Far = (InvD[A] < 0 ? Lo : Hi)[A]->s[K];
          TN = std::max(TN, (Near - O[A]) * InvD[A]);
          TF = std::min(TF, (Far - O[A]) * InvD[A]);
        }
        if (TN <= TF) { // insertion, nearest first
          int I = M++;
          for (; I > 0 && Hit[I - 1].second > TN; --I)
            Hit[I] = Hit[I - 1];
          Hit[I] = {N.child.s[K], TN};
        }
      }
      for (int K = M - 1; K > 0; --K)
        Stack.push_back(Hit[K]);
      if (M > 0) {
        Ref = Hit[0].first;
        continue;
      }
    } else {
      uint32_t V = ~uint32_t(Ref);
      int First = int(V >> RT_BVH_LEAF_BITS), Count = int(V & ((1u << RT_BVH_LEAF_BITS) - 1));
      for (int T = First; T < First + Count; ++T) {
        float Hit = intersectTriangle(P[3 * T], P[3 * T + 1], P[3 * T + 2], O, D, TMin, H.T);
        if (Hit > 0) {
          H.T = Hit, H.Tri = T;
          if (AnyHit)
            return H;
        }
      }
    }
    bool Found = false;
    while (!Found && !Stack.empty()) {
      auto [R, Entry] = Stack.back();
      Stack.pop_back();
      if (Entry <= H.T)
        Ref = R, Found = true;
    }
    if (!Found)
      return H;
  }
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
