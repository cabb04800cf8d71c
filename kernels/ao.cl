/* ao.cl: ambient occlusion. The default is two kernels: ao_trace runs numActive * aoSamples
 * work-items in one launch (work-item k traces AO ray k % aoSamples of hit k / aoSamples:
 * cosine-weighted around the shading normal, any-hit, up to aoDistance; only hits whose
 * material's textures read AO trace, the other work-items return at once); ao_reduce averages
 * each hit's rays into TexccHitAttrs.uvAO.z (1 = unoccluded) and counts the AO rays traced.
 * ao_loop is the alternative the paper argues against, kept to measure it (texrender
 * --ao-method=loop): one work-item per hit traces its aoSamples rays in a loop. Both trace
 * the very same rays (their directions from ao_dirs8), so the images are identical. */
#include "rt_bvh.h"
#include "rt_surface.h"

/* Whether hit i's material reads AO (the other hits trace no AO rays). */
static inline bool ao_wanted(RtHit h, __global const RtTriAttr *triAttrs, __global const RtMesh *meshes,
                      __global const RtMaterial *materials) {
  return h.tri >= 0 && materials[meshes[triAttrs[h.tri].mesh].material].readsAo;
}

/* The directions of AO rays j0 .. j0 + 7 of the path p's hit at surface s (rt_surface of the
 * hit), one per lane: cosine-weighted around the shading normal as Cycles' AO node draws them.
 * This is the one definition of an AO ray's direction: ao_dir_at takes its lane j % 8, ao_rays
 * all 8. It makes 8 at once because this maths was 85% of ao_rays' time and PoCL runs it as
 * SIMD only written on vector types (float8: about 3x faster than 8 scalar rays, the same
 * bits; bench/cycles.md, 2026-12-04). */
static inline void ao_dirs8(RtSurface s, __global const RtPath *p, int j0, int aoSamples,
                            uint seed, float8 *dx, float8 *dy, float8 *dz) {
  float8 u1, u2;
#ifdef RT_SAMPLER_PCG
  float a1[8], a2[8];
  for (int k = 0; k < 8; ++k) {
    uint rng = rt_seed(p->rng, (uint)(j0 + k), seed ^ 0xA0A0A0A0u);
    a1[k] = rt_rand(&rng);
    a2[k] = rt_rand(&rng);
  }
  u1 = vload8(0, a1), u2 = vload8(0, a2);
#else
  /* The hit's aoSamples rays are the first points of one fully Owen-scrambled Sobol pattern
   * seeded per hit (rt_owen_net2_8 over the 2^levels points that hold them): stratified among
   * themselves and distributed as the rays of Cycles' AO node are (an aligned block of its
   * tabulated Owen-scrambled Sobol points). The estimate's distribution matters beyond noise:
   * a texture maps it through nonlinear nodes (the rust mask's smoothstep), whose mean then
   * depends on it (issue 22: independent rays moved the rust colour by up to 3% from Cycles';
   * rt_sobol2's hashed scramble on 8 points, up to 5%). */
  uint levels = aoSamples > 1 ? 32u - clz((uint)aoSamples - 1u) : 0u;
  rt_owen_net2_8((uint)j0 + (uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u), levels,
                 rt_seed(p->rng, 0x5A0u, seed ^ 0xA0A0A0A0u), &u1, &u2);
#endif
  /* Cycles' warp and frame (svm_ao: sample_uniform_disk lifted, make_orthonormals of the
   * shading normal): the stratified points become the same kind of direction set, so the
   * estimate spreads as Cycles' does, and a nonlinear node after it (rust's smoothstep) gets
   * Cycles' mean. Issue 22: with the polar warp in Duff's frame the AO's own mean per 8x8
   * block agreed with Cycles' within 0.54%, its per-pixel spread differed by -25% to +75%,
   * and rust's colour was off by up to 6.2% in 16 of 74 smooth blocks. */
  float8 x, y, z;
  rt_sample_cosine_concentric8(u1, u2, &x, &y, &z);
  float3 t, b, n = s.ns;
  rt_frame_cycles(n, &t, &b);
  *dx = x * t.x + y * b.x + z * n.x;
  *dy = x * t.y + y * b.y + z * n.y;
  *dz = x * t.z + y * b.z + z * n.z;
}

/* Where every AO ray starts: on the hit point, as Cycles' AO node starts its rays (svm_ao:
 * ray.P = sd->P, tmin 0, its own triangle skipped, ray.self.prim): a face through the hit point
 * occludes it (Embree's robust test, which Cycles uses, takes t = tmin). texrender starts it
 * 1e-6 (1 + |p|) behind the hit point along its direction (tmin 0), so that such a face is hit
 * at t > 0 by every backend and Embree needs no robust mode (robust: +17% to the closest hits
 * and +21% to the AO packets, 256x256 4 spp rust-all), and skips the hit's own triangle (s.tri). Issue 22: the atrium's gears have
 * such faces (their teeth overlap, their flat sides in one plane), fully occluded slits in
 * Cycles' AO that texrender's origin offset along the normal (1e-4 (1 + |p|), before) never
 * hit: 4 blocks there 11-24% lighter than Cycles' (bench/cycles.md, session 9). */
static inline float3 ao_origin(RtSurface s, float3 dir) {
  return s.p - 1e-6f * (1.0f + rt_max3(fabs(s.p))) * dir;
}

/* The direction of AO ray j of the path p's hit at surface s (lane j % 8 of ao_dirs8). */
static inline float3 ao_dir_at(RtSurface s, __global const RtPath *p, int j, int aoSamples,
                               uint seed) {
  float8 dx, dy, dz;
  ao_dirs8(s, p, j & ~7, aoSamples, seed, &dx, &dy, &dz);
  float ax[8], ay[8], az[8];
  vstore8(dx, 0, ax), vstore8(dy, 0, ay), vstore8(dz, 0, az);
  return (float3)(ax[j & 7], ay[j & 7], az[j & 7]);
}

/* AO ray j of the path p's hit h: 1 if it hits something within aoDistance. */
static inline int ao_occluded(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                       __global const RtTriAttr *triAttrs, __global const RtPath *p, RtHit h,
                       int j, int aoSamples, float aoDistance, uint seed) {
  RtSurface s = rt_surface(tris, triAttrs, p->origin.xyz, p->dir.xyz, h);
  float3 dir = ao_dir_at(s, p, j, aoSamples, seed);
  return rt_trace_skip(nodes, tris, ao_origin(s, dir), dir, 0.0f, aoDistance, 1, s.tri).tri >= 0;
}

/* The AO rays of a host trace backend (Embree, runtime/lib/TraceEmbree.cpp): ray k = ray
 * k % aoSamples of hit k / aoSamples, exactly the ray ao_trace traces, as an RtShadowRay
 * (origin.w = the bits of the triangle it skips, as_float(s.tri); dir.w = aoDistance,
 * contrib.w = 1). A hit whose material does not read AO writes only its
 * first ray's contrib, with w = -aoSamples: the host skips its aoSamples rays (their slots
 * hold stale rays; ao_reduce does not read their results). One work-item per hit (numActive
 * of them): the surface is reconstructed once for the hit's aoSamples rays, their directions
 * made 8 at a time (ao_dirs8). */
__kernel void ao_rays(__global const RtTri *tris, __global const RtTriAttr *triAttrs,
                      __global const RtPath *paths, __global const int *active, int numActive,
                      __global const RtHit *hits, __global const RtMesh *meshes,
                      __global const RtMaterial *materials, int aoSamples, float aoDistance,
                      uint seed, __global RtShadowRay *rays) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtHit h = hits[i];
  __global RtShadowRay *out = rays + (size_t)i * (size_t)aoSamples;
  if (!ao_wanted(h, triAttrs, meshes, materials)) {
    out[0].contrib = (float4)(0.0f, 0.0f, 0.0f, -(float)aoSamples);
    return;
  }
  __global const RtPath *p = &paths[active[i]];
  RtSurface s = rt_surface(tris, triAttrs, p->origin.xyz, p->dir.xyz, h);
  for (int j0 = 0; j0 < aoSamples; j0 += 8) {
    float8 dx, dy, dz;
    ao_dirs8(s, p, j0, aoSamples, seed, &dx, &dy, &dz);
    float ax[8], ay[8], az[8];
    vstore8(dx, 0, ax), vstore8(dy, 0, ay), vstore8(dz, 0, az);
    for (int k = 0; k < 8 && j0 + k < aoSamples; ++k) {
      float3 dir = (float3)(ax[k], ay[k], az[k]);
      out[j0 + k].origin = (float4)(ao_origin(s, dir), as_float(s.tri));
      out[j0 + k].dir = (float4)(dir, aoDistance);
      out[j0 + k].contrib = (float4)(0.0f, 0.0f, 0.0f, 1.0f);
    }
  }
}

__kernel void ao_trace(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                       __global const RtTriAttr *triAttrs, __global const RtPath *paths,
                       __global const int *active, int numActive, __global const RtHit *hits,
                       __global const RtMesh *meshes, __global const RtMaterial *materials,
                       int aoSamples, float aoDistance, uint seed, __global uchar *occluded) {
  int k = get_global_id(0);
  if (k >= numActive * aoSamples)
    return;
  int i = k / aoSamples;
  int j = k % aoSamples;
  RtHit h = hits[i];
  if (!ao_wanted(h, triAttrs, meshes, materials)) {
    occluded[k] = 0;
    return;
  }
  occluded[k] = (uchar)ao_occluded(nodes, tris, triAttrs, &paths[active[i]], h, j, aoSamples,
                                   aoDistance, seed);
}

__kernel void ao_reduce(__global const uchar *occluded, __global const RtHit *hits,
                        __global const RtTriAttr *triAttrs, __global const RtMesh *meshes,
                        __global const RtMaterial *materials, int numActive, int aoSamples,
                        __global TexccHitAttrs *attrs, __global uint *counters) {
  int i = get_global_id(0);
  if (i >= numActive || !ao_wanted(hits[i], triAttrs, meshes, materials))
    return;
  atomic_add(&counters[RT_COUNT_AO_RAYS], (uint)aoSamples);
  int n = 0;
  for (int j = 0; j < aoSamples; ++j)
    n += occluded[i * aoSamples + j];
  attrs[i].uvAO.z = 1.0f - (float)n / (float)aoSamples;
}

__kernel void ao_loop(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                      __global const RtTriAttr *triAttrs, __global const RtPath *paths,
                      __global const int *active, int numActive, __global const RtHit *hits,
                      __global const RtMesh *meshes, __global const RtMaterial *materials,
                      int aoSamples, float aoDistance, uint seed, __global TexccHitAttrs *attrs,
                      __global uint *counters) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtHit h = hits[i];
  if (!ao_wanted(h, triAttrs, meshes, materials))
    return;
  atomic_add(&counters[RT_COUNT_AO_RAYS], (uint)aoSamples);
  __global const RtPath *p = &paths[active[i]];
  RtSurface s = rt_surface(tris, triAttrs, p->origin.xyz, p->dir.xyz, h);
  int n = 0;
  for (int j0 = 0; j0 < aoSamples; j0 += 8) { /* the rays of ao_occluded, 8 directions at once */
    float8 dx, dy, dz;
    ao_dirs8(s, p, j0, aoSamples, seed, &dx, &dy, &dz);
    float ax[8], ay[8], az[8];
    vstore8(dx, 0, ax), vstore8(dy, 0, ay), vstore8(dz, 0, az);
    for (int k = 0; k < 8 && j0 + k < aoSamples; ++k) {
      float3 dir = (float3)(ax[k], ay[k], az[k]);
      n += rt_trace_skip(nodes, tris, ao_origin(s, dir), dir, 0.0f, aoDistance, 1, s.tri).tri >= 0;
    }
  }
  attrs[i].uvAO.z = 1.0f - (float)n / (float)aoSamples;
}
