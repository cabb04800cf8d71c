/* rt_bvh.h: ray-triangle intersection and BVH traversal (closest hit and any hit), shared by the
 * closest-hit, shadow and AO kernels. OpenCL C 1.2. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include "rt_types.h"



/* Moeller-Trumbore; returns t in (tmin, tmax) or a negative value, with barycentrics. */
static inline float rt_intersect_tri(__global const RtTri *tri, float3 o, float3 d, float tmin,
                              float tmax, float *bu, float *bv) {
  float3 e1 = tri->e1.xyz, e2 = tri->e2.xyz;
  float3 p = cross(d, e2);
  float det = dot(e1, p);
  if (fabs(det) < 1e-20f)
    return -1.0f;
  float inv = 1.0f / det;
  float3 s = o - tri->v0.xyz;
  float u = dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f)
    return -1.0f;
  float3 q = cross(s, e1);
  float v = dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f)
    return -1.0f;
  float t = dot(e2, q) * inv;
  if (t <= tmin || t >= tmax)
    return -1.0f;
  *bu = u;
  *bv = v;
  return t;
}

/* Slab test; returns the entry distance or a value > tmax on a miss. */
static inline float rt_intersect_box(__global const RtBvhNode *n, float3 o, float3 invd, float tmax) {
  float3 bmin = (float3)(n->bmin[0], n->bmin[1], n->bmin[2]);
  float3 bmax = (float3)(n->bmax[0], n->bmax[1], n->bmax[2]);
  float3 t0 = (bmin - o) * invd;
  float3 t1 = (bmax - o) * invd;
  float3 lo = fmin(t0, t1), hi = fmax(t0, t1);
  float tn = fmax(fmax(lo.x, lo.y), fmax(lo.z, 0.0f));
  float tf = fmin(fmin(hi.x, hi.y), fmin(hi.z, tmax));
  return tn <= tf ? tn : INFINITY;
}

static inline float3 rt_safe_inverse(float3 d) {
  const float tiny = 1e-30f;
  return (float3)(1.0f / (fabs(d.x) > tiny ? d.x : copysign(tiny, d.x)),
                  1.0f / (fabs(d.y) > tiny ? d.y : copysign(tiny, d.y)),
                  1.0f / (fabs(d.z) > tiny ? d.z : copysign(tiny, d.z)));
}

/* Traverses the BVH. anyHit: stop at the first intersection (shadow and AO rays). Returns the
 * hit (tri = -1 on a miss). */
static inline RtHit rt_trace(__global const RtBvhNode *nodes, __global const RtTri *tris, float3 o,
                      float3 d, float tmin, float tmax, int anyHit) {
  RtHit hit;
  hit.t = tmax;
  hit.tri = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  float3 invd = rt_safe_inverse(d);
  int stack[RT_BVH_STACK];
  float entry[RT_BVH_STACK]; /* the entry distance of each stacked node */
  int sp = 0;
  int node = 0;
  if (rt_intersect_box(&nodes[0], o, invd, hit.t) == INFINITY)
    return hit;
  while (1) {
    __global const RtBvhNode *n = &nodes[node];
    if (n->count > 0) {
      for (int i = 0; i < n->count; ++i) {
        int ti = n->leftFirst + i;
        float u, v;
        float t = rt_intersect_tri(&tris[ti], o, d, tmin, hit.t, &u, &v);
        if (t > 0.0f) {
          hit.t = t;
          hit.tri = ti;
          hit.u = u;
          hit.v = v;
          if (anyHit)
            return hit;
        }
      }
    } else {
      int c0 = n->leftFirst, c1 = n->leftFirst + 1;
      float d0 = rt_intersect_box(&nodes[c0], o, invd, hit.t);
      float d1 = rt_intersect_box(&nodes[c1], o, invd, hit.t);
      if (d0 > d1) {
        float td = d0; d0 = d1; d1 = td;
        int tc = c0; c0 = c1; c1 = tc;
      }
      if (d0 != INFINITY) {
        if (d1 != INFINITY && sp < RT_BVH_STACK) {
          stack[sp] = c1;
          entry[sp++] = d1;
        }
        node = c0;
        continue;
      }
    }
    /* Pop the nearest pending node that can still hold a closer hit. */
    node = -1;
    while (sp > 0) {
      --sp;
      if (entry[sp] <= hit.t) {
        node = stack[sp];
        break;
      }
    }
    if (node < 0)
      break;
  }
  return hit;
}

#endif
