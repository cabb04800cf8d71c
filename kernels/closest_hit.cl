/* closest_hit.cl: the nearest intersection of each active path's ray (BVH traversal). Hit i
 * belongs to path active[i]. */
#include "rt_bvh.h"

__kernel void closest_hit(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                          __global const RtPath *paths, __global const int *active, int numActive,
                          __global RtHit *hits) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  __global const RtPath *p = &paths[active[i]];
  hits[i] = rt_trace(nodes, tris, p->origin.xyz, p->dir.xyz, 0.0f, INFINITY, 0);
}
