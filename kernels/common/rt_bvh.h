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

static inline float3 rt_safe_inverse(float3 d) {
  const float tiny = 1e-30f;
  return (float3)(1.0f / (fabs(d.x) > tiny ? d.x : copysign(tiny, d.x)),
                  1.0f / (fabs(d.y) > tiny ? d.y : copysign(tiny, d.y)),
                  1.0f / (fabs(d.z) > tiny ? d.z : copysign(tiny, d.z)));
}

/* Inserts child ref c with entry distance t into the list (cs, ds, m) sorted nearest first,
 * when h (its slab test) is true. */
#define RT_BVH_INSERT(h, c, t)                                                                   \
  if (h) {                                                                                       \
    int k_ = m++;                                                                                \
    while (k_ > 0 && ds[k_ - 1] > (t)) {                                                         \
      ds[k_] = ds[k_ - 1];                                                                       \
      cs[k_] = cs[k_ - 1];                                                                       \
      --k_;                                                                                      \
    }                                                                                            \
    ds[k_] = (t);                                                                                \
    cs[k_] = (c);                                                                                \
  }

/* Traverses the wide BVH (RtBvh4Node: 4 children tested at once with float4 slab tests, the
 * nearest hit child next, the others stacked farthest first). anyHit: stop at the first
 * intersection (shadow and AO rays). skip: a triangle never hit (an AO ray's own, which it
 * starts on; -1: none). Returns the hit (tri = -1 on a miss). */
static inline RtHit rt_trace_skip(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                                  float3 o, float3 d, float tmin, float tmax, int anyHit,
                                  int skip) {
  RtHit hit;
  hit.t = tmax;
  hit.tri = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  float3 invd = rt_safe_inverse(d);
  /* Per axis, the near plane is the box's min when the direction is positive: an empty slot
   * (min > max) then gives tnear > tfar on every ray. */
  const int nx = invd.x < 0.0f, ny = invd.y < 0.0f, nz = invd.z < 0.0f;
  const float4 ox = (float4)(o.x), oy = (float4)(o.y), oz = (float4)(o.z);
  const float4 ix = (float4)(invd.x), iy = (float4)(invd.y), iz = (float4)(invd.z);
  int stack[RT_BVH_STACK];
  float entry[RT_BVH_STACK]; /* the entry distance of each stacked child */
  int sp = 0;
  int ref = 0;
  while (1) {
    if (ref >= 0) {
      __global const RtBvh4Node *n = &nodes[ref];
      float4 tnx = ((nx ? n->hix : n->lox) - ox) * ix, tfx = ((nx ? n->lox : n->hix) - ox) * ix;
      float4 tny = ((ny ? n->hiy : n->loy) - oy) * iy, tfy = ((ny ? n->loy : n->hiy) - oy) * iy;
      float4 tnz = ((nz ? n->hiz : n->loz) - oz) * iz, tfz = ((nz ? n->loz : n->hiz) - oz) * iz;
      float4 tn = fmax(fmax(tnx, tny), fmax(tnz, (float4)(0.0f)));
      float4 tf = fmin(fmin(tfx, tfy), fmin(tfz, (float4)(hit.t)));
      int4 enter = tn <= tf;
      int4 c = n->child;
      int cs[4];
      float ds[4];
      int m = 0;
      RT_BVH_INSERT(enter.x, c.x, tn.x);
      RT_BVH_INSERT(enter.y, c.y, tn.y);
      RT_BVH_INSERT(enter.z, c.z, tn.z);
      RT_BVH_INSERT(enter.w, c.w, tn.w);
      if (m > 0) {
        for (int k = m - 1; k > 0; --k)
          if (sp < RT_BVH_STACK) {
            stack[sp] = cs[k];
            entry[sp++] = ds[k];
          }
        ref = cs[0];
        continue;
      }
    } else {
      int v = ~ref;
      int first = v >> RT_BVH_LEAF_BITS, count = v & ((1 << RT_BVH_LEAF_BITS) - 1);
      for (int ti = first; ti < first + count; ++ti) {
        if (ti == skip)
          continue;
        float u, w;
        float t = rt_intersect_tri(&tris[ti], o, d, tmin, hit.t, &u, &w);
        if (t > 0.0f) {
          hit.t = t;
          hit.tri = ti;
          hit.u = u;
          hit.v = w;
          if (anyHit)
            return hit;
        }
      }
    }
    /* Pop the nearest pending child that can still hold a closer hit. */
    int found = 0;
    while (sp > 0 && !found) {
      --sp;
      if (entry[sp] <= hit.t) {
        ref = stack[sp];
        found = 1;
      }
    }
    if (!found)
      break;
  }
  return hit;
}

static inline RtHit rt_trace(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                             float3 o, float3 d, float tmin, float tmax, int anyHit) {
  return rt_trace_skip(nodes, tris, o, d, tmin, tmax, anyHit, -1);
}

#undef RT_BVH_INSERT

#endif
