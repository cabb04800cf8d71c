#ifndef TEXRENDER_BVH_H
#define TEXRENDER_BVH_H

// The wide BVH of the OpenCL traversal (kernels/common/rt_bvh.h): 4 children per node, built on
// the host by Embree's BVH builder (rtcBuildBVH, binned SAH) and flattened into RtBvh4Node
// (children's boxes as SoA float4, child references as int4); leaves index a triangle array
// reordered into leaf order.

#include "texrender/Scene.h"

#include <cstdint>
#include <vector>

extern "C" {
#include "rt_types.h"
}

namespace texrender {

struct Bvh {
  std::vector<RtBvh4Node> Nodes; // Nodes[0] is the root
  std::vector<uint32_t> Order;   // Order[k]: the input triangle stored at position k
  unsigned Depth = 0;            // levels of inner nodes below the root
  double BuildSeconds = 0;       // wall clock of buildBvh (Embree's builder and the flattening)
};

/// Builds over Positions (3 per triangle). Leaves hold at most MaxLeaf (<= RT_BVH_MAX_LEAF)
/// triangles; the depth stays within RT_BVH_MAX_DEPTH (the device traversal stack).
Bvh buildBvh(const std::vector<Vec3> &Positions, unsigned MaxLeaf = 4);

struct HostHit {
  float T = 0;
  int Tri = -1; // index in BVH order
};

/// Host traversal (for tests), the device's algorithm: the closest hit in (TMin, TMax), or any
/// hit when AnyHit. Positions are in BVH order (3 per triangle).
HostHit traceHost(const Bvh &B, const std::vector<Vec3> &Positions, const Vec3 &O,
                  const Vec3 &D, float TMin, float TMax, bool AnyHit);
/// Brute force over every triangle (the oracle of the tests).
HostHit traceBruteForce(const std::vector<Vec3> &Positions, const Vec3 &O, const Vec3 &D,
                        float TMin, float TMax);
/// One ray-triangle test (Moeller-Trumbore, as the device); T < 0 on a miss.
float intersectTriangle(const Vec3 &V0, const Vec3 &V1, const Vec3 &V2, const Vec3 &O,
                        const Vec3 &D, float TMin, float TMax);

} // namespace texrender

#endif
