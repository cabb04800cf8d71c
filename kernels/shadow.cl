/* shadow.cl: any-hit traversal of the shadow rays made by `shade`; an unoccluded ray adds its
 * radiance to its path. Shadow ray i belongs to path active[i]. */
#include "rt_bvh.h"

__kernel void shadow(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                     __global const RtShadowRay *rays, __global RtPath *paths,
                     __global const int *active, int numActive) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtShadowRay r = rays[i];
  if (r.contrib.w <= 0.0f)
    return;
  RtHit h = rt_trace(nodes, tris, r.origin.xyz, r.dir.xyz, 0.0f, r.dir.w, 1);
  if (h.tri < 0)
    paths[active[i]].radiance.xyz += r.contrib.xyz;
}
