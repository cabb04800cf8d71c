#ifndef TEXRENDER_BVH_H
#define TEXRENDER_BVH_H

// A binned-SAH BVH over triangles, built on the host and flattened for the OpenCL traversal
// (kernels/common/rt_bvh.h): siblings are adjacent, leaves index a reordered triangle array.

#include "texrender/Scene.h"

#include <cstdint>
#include <vector>

extern "C" {
#include "rt_types.h"
}

namespace texrender {

struct Bvh {
  std::vector<RtBvhNode> Nodes;
  std::vector<uint32_t> Order; // Order[k]: the input triangle stored at position k
  unsigned Depth = 0;
  double BuildSeconds = 0; // wall clock of buildBvh
};

/// Builds over Positions (3 per triangle). Leaves hold at most MaxLeaf triangles; the depth
/// stays below the device traversal stack (RT_BVH_STACK).
Bvh buildBvh(const std::vector<Vec3> &Positions, unsigned MaxLeaf = 4);

struct HostHit {
  float T = 0;
  int Tri = -1; // index in BVH order
};

/// Host traversal (for tests): the closest hit in (TMin, TMax), or any hit when AnyHit.
/// Positions are in BVH order (3 per triangle).
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
