/* ao.cl: ambient occlusion. The default is two kernels: ao_trace runs numActive * aoSamples
 * work-items in one launch (work-item k traces AO ray k % aoSamples of hit k / aoSamples:
 * cosine-weighted around the shading normal, any-hit, up to aoDistance; only hits whose
 * material's textures read AO trace, the other work-items return at once); ao_reduce averages
 * each hit's rays into TexccHitAttrs.uvAO.z (1 = unoccluded) and counts the AO rays traced.
 * ao_loop is the alternative the paper argues against, kept to measure it (texrender
 * --ao-method=loop): one work-item per hit traces its aoSamples rays in a loop. Both trace
 * the very same rays (ao_occluded), so the images are identical. */
#include "rt_bvh.h"
#include "rt_surface.h"

/* Whether hit i's material reads AO (the other hits trace no AO rays). */
static inline bool ao_wanted(RtHit h, __global const RtTriAttr *triAttrs, __global const RtMesh *meshes,
                      __global const RtMaterial *materials) {
  return h.tri >= 0 && materials[meshes[triAttrs[h.tri].mesh].material].readsAo;
}

/* AO ray j of the path p's hit h at surface s (rt_surface of h): its origin and direction
 * (cosine-weighted around the shading normal as Cycles' AO node draws them, offset off the
 * surface). */
static inline void ao_ray_at(RtSurface s, __global const RtPath *p, int j, float eps, uint seed,
                             float3 *o, float3 *dir) {
#ifdef RT_SAMPLER_PCG
  uint rng = rt_seed(p->rng, (uint)j, seed ^ 0xA0A0A0A0u);
  float u1 = rt_rand(&rng), u2 = rt_rand(&rng);
#else
  /* The hit's aoSamples rays are the first points of one Owen-scrambled Sobol pattern seeded
   * per hit: stratified among themselves, as the rays of Cycles' AO node are. The estimate's
   * variance matters beyond noise: a texture maps it through nonlinear nodes (the rust mask's
   * smoothstep), whose mean then depends on it (issue 22: independent rays moved the rust
   * colour by up to 3% from Cycles'). */
  float2 u = rt_sobol2((uint)j, rt_seed(p->rng, 0x5A0u, seed ^ 0xA0A0A0A0u));
  float u1 = u.x, u2 = u.y;
#endif
  /* Cycles' warp and frame (svm_ao: sample_uniform_disk lifted, make_orthonormals of the
   * shading normal): the stratified points become the same kind of direction set, so the
   * estimate spreads as Cycles' does, and a nonlinear node after it (rust's smoothstep) gets
   * Cycles' mean. Issue 22: with the polar warp in Duff's frame the AO's own mean per 8x8
   * block agreed with Cycles' within 0.54%, its per-pixel spread differed by -25% to +75%,
   * and rust's colour was off by up to 6.2% in 16 of 74 smooth blocks. */
  *dir = rt_to_world_cycles(rt_sample_cosine_concentric(u1, u2), s.ns);
  *o = rt_offset(s, *dir, eps);
}

/* AO ray j of the path p's hit h: its origin and direction. */
static inline void ao_ray(__global const RtTri *tris, __global const RtTriAttr *triAttrs,
                          __global const RtPath *p, RtHit h, int j, float eps, uint seed,
                          float3 *o, float3 *dir) {
  ao_ray_at(rt_surface(tris, triAttrs, p->origin.xyz, p->dir.xyz, h), p, j, eps, seed, o, dir);
}

/* AO ray j of the path p's hit h: 1 if it hits something within aoDistance. */
static inline int ao_occluded(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                       __global const RtTriAttr *triAttrs, __global const RtPath *p, RtHit h,
                       int j, float aoDistance, float eps, uint seed) {
  float3 o, dir;
  ao_ray(tris, triAttrs, p, h, j, eps, seed, &o, &dir);
  RtHit ah = rt_trace(nodes, tris, o, dir, 0.0f, aoDistance, 1);
  return ah.tri >= 0 ? 1 : 0;
}

/* The AO rays of a host trace backend (Embree, runtime/lib/TraceEmbree.cpp): ray k = ray
 * k % aoSamples of hit k / aoSamples, exactly the ray ao_trace traces, as an RtShadowRay
 * (dir.w = aoDistance, contrib.w = 1). A hit whose material does not read AO writes only its
 * first ray's contrib, with w = -aoSamples: the host skips its aoSamples rays (their slots
 * hold stale rays; ao_reduce does not read their results). One work-item per hit (numActive
 * of them): the surface is reconstructed once for the hit's aoSamples rays. */
__kernel void ao_rays(__global const RtTri *tris, __global const RtTriAttr *triAttrs,
                      __global const RtPath *paths, __global const int *active, int numActive,
                      __global const RtHit *hits, __global const RtMesh *meshes,
                      __global const RtMaterial *materials, int aoSamples, float aoDistance,
                      float eps, uint seed, __global RtShadowRay *rays) {
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
  for (int j = 0; j < aoSamples; ++j) {
    float3 o, dir;
    ao_ray_at(s, p, j, eps, seed, &o, &dir);
    out[j].origin = (float4)(o, 0.0f);
    out[j].dir = (float4)(dir, aoDistance);
    out[j].contrib = (float4)(0.0f, 0.0f, 0.0f, 1.0f);
  }
}

__kernel void ao_trace(__global const RtBvh4Node *nodes, __global const RtTri *tris,
                       __global const RtTriAttr *triAttrs, __global const RtPath *paths,
                       __global const int *active, int numActive, __global const RtHit *hits,
                       __global const RtMesh *meshes, __global const RtMaterial *materials,
                       int aoSamples, float aoDistance, float eps, uint seed,
                       __global uchar *occluded) {
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
  occluded[k] = (uchar)ao_occluded(nodes, tris, triAttrs, &paths[active[i]], h, j, aoDistance,
                                   eps, seed);
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
                      int aoSamples, float aoDistance, float eps, uint seed,
                      __global TexccHitAttrs *attrs, __global uint *counters) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtHit h = hits[i];
  if (!ao_wanted(h, triAttrs, meshes, materials))
    return;
  atomic_add(&counters[RT_COUNT_AO_RAYS], (uint)aoSamples);
  int n = 0;
  for (int j = 0; j < aoSamples; ++j)
    n += ao_occluded(nodes, tris, triAttrs, &paths[active[i]], h, j, aoDistance, eps, seed);
  attrs[i].uvAO.z = 1.0f - (float)n / (float)aoSamples;
}
