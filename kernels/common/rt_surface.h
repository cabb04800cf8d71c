/* rt_surface.h: the surface at a hit (position, normals facing the incoming ray, texture
 * coordinates), shared by the hit-attributes, AO and shading kernels. OpenCL C 1.2. */
#ifndef RT_SURFACE_H
#define RT_SURFACE_H

#include "rt_sampling.h"
#include "rt_types.h"

typedef struct RtSurface {
  float3 p;       /* world position */
  float3 ng;      /* geometric normal, facing the incoming ray */
  float3 ns;      /* shading normal, on the side of ng */
  float2 uv;
  int front;      /* the ray hit the side the triangle's winding faces */
  int tri;
} RtSurface;

static inline RtSurface rt_surface(__global const RtTri *tris, __global const RtTriAttr *attrs,
                            float3 o, float3 d, RtHit h) {
  RtSurface s;
  __global const RtTri *t = &tris[h.tri];
  __global const RtTriAttr *a = &attrs[h.tri];
  float b0 = 1.0f - h.u - h.v;
  s.tri = h.tri;
  s.p = t->v0.xyz + h.u * t->e1.xyz + h.v * t->e2.xyz;
  float3 ng = normalize(cross(t->e1.xyz, t->e2.xyz));
  s.front = dot(ng, d) < 0.0f;
  if (!s.front)
    ng = -ng;
  s.ng = ng;
  float3 ns = ng;
  if (a->n0.w > 0.0f) {
    float3 n = b0 * a->n0.xyz + h.u * a->n1.xyz + h.v * a->n2.xyz;
    float len = length(n);
    if (len > 0.0f) {
      ns = n / len;
      if (dot(ns, ng) < 0.0f)
        ns = -ns;
    }
  }
  s.ns = ns;
  s.uv = b0 * a->uv01.xy + h.u * a->uv01.zw + h.v * a->uv2.xy;
  return s;
}

/* Where a ray leaving the surface starts: offset along the geometric normal, on the side of
 * the outgoing direction, by an amount that grows with the magnitude of the position. */
static inline float3 rt_offset(RtSurface s, float3 dir, float eps) {
  float scale = eps * (1.0f + rt_max3(fabs(s.p)));
  return s.p + (dot(dir, s.ng) >= 0.0f ? scale : -scale) * s.ng;
}

#endif
