/* shade.cl: one path vertex per active hit. Adds emission (the lamps the segment crossed and
 * emissive meshes, with MIS against light sampling; sky, environment map and sun on a miss; a principled leaf's
 * emission), picks a BSDF leaf of the material's tree (a blend chooses
 * `b` with probability mask), makes one next-event-estimation shadow ray (light chosen by the
 * light CDF, the sun and the sky sharing their part by contribution; MIS, power heuristic), samples the next direction, applies Russian roulette and
 * writes the next ray. Path length follows Mitsuba's max_depth. */
#include "rt_bsdf.h"
#include "rt_env.h"
#include "rt_lamps.h"
#include "rt_surface.h"

/* Bench-only split of the image by light and by path length (bench/sampling.py,
 * docs/sampling.md): compiled with -D RT_SPLIT_LIGHTS=mask (RT_SPLIT_* below) and optionally
 * RT_SPLIT_MIN_LENGTH / RT_SPLIT_MAX_LENGTH (path length in segments: 1 = an emitter seen
 * from the camera, 2 = direct light), only those contributions reach the image; the sampling
 * (and so the random stream) is unchanged. Without RT_SPLIT_LIGHTS RT_KEEP is the constant 1. */
#define RT_SPLIT_MESH 1     /* emissive meshes (area lights) */
#define RT_SPLIT_SUN 2
#define RT_SPLIT_SKY 4      /* the sky or the environment map */
#define RT_SPLIT_MATERIAL 8 /* emission of materials (emission leaves, principled emission) */
#define RT_SPLIT_LAMP 16    /* point, spot and area lamps */
#ifdef RT_SPLIT_LIGHTS
#ifndef RT_SPLIT_MIN_LENGTH
#define RT_SPLIT_MIN_LENGTH 0
#endif
#ifndef RT_SPLIT_MAX_LENGTH
#define RT_SPLIT_MAX_LENGTH 1000000
#endif
#define RT_KEEP(kind, length)                                                                  \
  (((RT_SPLIT_LIGHTS) & (kind)) && (length) >= RT_SPLIT_MIN_LENGTH &&                          \
           (length) <= RT_SPLIT_MAX_LENGTH                                                     \
       ? 1.0f                                                                                  \
       : 0.0f)
#else
#define RT_KEEP(kind, length) 1.0f
#endif

static inline float4 rt_input(RtBsdfInput in, __global const float4 *outputs, int base) {
  if (in.output < 0)
    return in.value;
  float4 v = outputs[base + in.output];
  return in.components == 1 ? (float4)(v.x) : v;
}

/* A NaN or infinite value (a texture's, a BSDF weight, a light sample's) makes the whole path
 * sample non-finite here, before anything clamps it away (fmax(NaN, 0) is 0, clamp() of NaN
 * is 0): accumulate then drops the sample and counts it (stats.json "nonFiniteSamples"). */
static inline int rt_finite3(float3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

static inline void rt_poison(__global RtPath *paths, int pid, RtPath p, uint rng) {
  p.radiance.x = NAN;
  p.flags &= ~RT_PATH_ALIVE;
  p.rng = rng;
  paths[pid] = p;
}

static inline int rt_pick_light(__global const float *cdf, int n, float u) {
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (u < cdf[mid])
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

/* The sun's share of the environment's selection probability at a vertex (docs/sampling.md):
 * when the scene has both a sun and a sky (adjacent in the light CDF), next-event estimation
 * splits their summed probability between them by their estimated contribution at the vertex,
 * as Cycles' light tree does for distant lights: the sun's irradiance (its power weight) times
 * the cosine between the shading normal and the nearest point of its disc, against the sky's
 * (pi times its radiance, whatever the normal) times RT_SKY_WEIGHT. The weight is below 1
 * because BSDF samples already estimate the constant sky about as well as a cosine-weighted
 * shadow ray does (MIS combines both), while only next-event estimation finds the small sun:
 * on the diffuse atrium (64x64, 64 spp, 8 seeds) the image's variance is 4.07e-5 with the
 * fixed share of the power weights, 4.45e-5 with weight 1, 3.14e-5 with 0.25, 2.87e-5 with
 * 0.05; 0.02 and 0.01 take 2.5% off that at the same CPU time (12 seeds, bench/sampling.md).
 * A sun wholly below the horizon gets no share (the sky every time). Bench-only
 * switches: RT_SUN_SHARE 0 the fixed share of before (the default with RT_SAMPLER_PCG),
 * 1 this rule, 2 Cycles' light-tree rule (the mean of the proportional share with the disc's
 * nearest and farthest points; 3.32e-5). The share is quantized to q / 65535 (q in 1..65534
 * when the sun can contribute, 0 when its disc is wholly below the horizon) and kept in the
 * path's flags (bits 16-31) for the MIS weight of a BSDF sample that reaches the sun, so both
 * sides of MIS use the very same probability (testsuite/runtime/sun-sky-sphere.test). */
#ifndef RT_SUN_SHARE
#ifdef RT_SAMPLER_PCG
#define RT_SUN_SHARE 0
#else
#define RT_SUN_SHARE 1
#endif
#endif
#ifndef RT_SKY_WEIGHT
#define RT_SKY_WEIGHT 0.02f
#endif
#define RT_SHARE_ONE 65535u

static inline int rt_env_split(RtShadeParams prm) {
  return RT_SUN_SHARE != 0 && prm.sunLight >= 0 && prm.skyLight >= 0 &&
         abs(prm.sunLight - prm.skyLight) == 1;
}

static inline uint rt_sun_share(__global const RtLight *lights, RtShadeParams prm, float3 n) {
  if (!rt_env_split(prm))
    return 0u;
  RtLight sun = lights[prm.sunLight];
  float r = sun.select / fmax(lights[prm.skyLight].select, 1e-30f);
  float c = dot(n, sun.dir.xyz), cu = sun.dir.w;
  float si = sqrt(fmax(0.0f, 1.0f - c * c)), su = sqrt(fmax(0.0f, 1.0f - cu * cu));
  float cmax = c >= cu ? 1.0f : c * cu + si * su; /* cos of the angle to the disc's nearest point */
  if (cmax <= 0.0f)
    return 0u;
#if RT_SUN_SHARE == 2
  float cmin = c * cu - si * su; /* ... and to its farthest point */
  float f = 0.5f * (r * cmax / (r * cmax + 1.0f)) + (cmin > 0.0f ? 0.5f : 0.25f);
#else
  float f = r * cmax / (r * cmax + (RT_SKY_WEIGHT));
#endif
  uint q = (uint)(f * (float)RT_SHARE_ONE + 0.5f);
  return clamp(q, 1u, RT_SHARE_ONE - 1u);
}

/* The selection probabilities of the sun and of the sky at a vertex whose sun share is q. */
static inline float rt_sun_select(__global const RtLight *lights, RtShadeParams prm, uint q) {
  if (!rt_env_split(prm))
    return lights[prm.sunLight].select;
  float env = lights[prm.sunLight].select + lights[prm.skyLight].select;
  return env * ((float)q / (float)RT_SHARE_ONE);
}

static inline float rt_sky_select(__global const RtLight *lights, RtShadeParams prm, uint q) {
  if (!rt_env_split(prm))
    return lights[prm.skyLight].select;
  float env = lights[prm.sunLight].select + lights[prm.skyLight].select;
  return env * ((float)(RT_SHARE_ONE - q) / (float)RT_SHARE_ONE);
}

/* Radiance arriving from the environment (sky and sun) along d, MIS-weighted against the pdf
 * with which next-event estimation would have chosen d at the previous vertex: the sun's from
 * its cone and its share there (sunShare), the sky's (cosine-weighted about the previous
 * vertex's shading normal) kept in skyPdf. */
static inline float3 rt_environment(__global const RtLight *lights, RtShadeParams prm,
                                    __global const float *envMap, float3 d, float bsdfPdf,
                                    float skyPdf, uint sunShare, int specular, int length) {
  float3 le = (float3)(0.0f);
  if (prm.envLight >= 0) {
    /* The environment map: its next-event density depends on d alone. */
    RtLight l = lights[prm.envLight];
    float w = specular ? 1.0f : rt_mis(bsdfPdf, l.select * rt_env_pdf(envMap, prm, l, d));
    le += rt_env_radiance(envMap, prm, l, d) * w * RT_KEEP(RT_SPLIT_SKY, length);
  }
  if (prm.skyLight >= 0) {
    RtLight l = lights[prm.skyLight];
    le += l.radiance.xyz * (specular ? 1.0f : rt_mis(bsdfPdf, skyPdf)) *
          RT_KEEP(RT_SPLIT_SKY, length);
  }
  if (prm.sunLight >= 0) {
    RtLight l = lights[prm.sunLight];
    if (dot(d, l.dir.xyz) >= l.dir.w) {
      float lp = rt_sun_select(lights, prm, sunShare) / (2.0f * RT_PI * (1.0f - l.dir.w));
      le += l.radiance.xyz * (specular ? 1.0f : rt_mis(bsdfPdf, lp)) *
            RT_KEEP(RT_SPLIT_SUN, length);
    }
  }
  return le;
}

/* The pdf with which next-event estimation picks direction wi for the sky at a vertex of
 * shading normal n and sun share q: the sky's selection probability times the cosine-weighted
 * density. */
static inline float rt_sky_pdf(__global const RtLight *lights, RtShadeParams prm, float3 n,
                               uint q, float3 wi) {
  return prm.skyLight >= 0
             ? rt_sky_select(lights, prm, q) * fmax(dot(wi, n), 0.0f) * RT_INV_PI
             : 0.0f;
}

/* Rescales u from [lo, lo + width) to [0, 1). */
static inline float rt_rescale(float u, float lo, float width) {
  return clamp((u - lo) / width, 0.0f, 0x1.fffffep-1f);
}

/* Samples a light from the surface point p of shading normal n (sun share q), the sky
 * cosine-weighted about n (its radiance is constant). u.xy is a 2D sampler point: u.x chooses
 * the light, and the part of u.x within the chosen light's CDF interval, rescaled, is the first
 * coordinate of the point on it (so the points of one light stay stratified); u.z (an
 * independent number) replaces it when the interval is too narrow for the float's bits. With
 * the sun and sky split by q, their joint CDF interval is divided again by q. Returns the
 * direction, the distance limit (0: a lamp that casts no shadow; no shadow ray is traced),
 * the emitted radiance and the solid-angle pdf (0: no contribution); *delta = 1 for a point
 * or spot lamp of radius 0 (then le / pdf is its irradiance, and no MIS applies). */
static inline float rt_sample_light(__global const RtLight *lights, __global const float *cdf,
                             __global const RtTri *tris, __global const float *envMap,
                             RtShadeParams prm, float3 p, float3 n, uint q, float3 u,
                             float3 *wi, float *tmax, float3 *le, int *type, int *delta) {
#ifdef RT_SAMPLER_PCG
  int li = rt_pick_light(cdf, prm.numLights, u.z); /* the stream's order of before */
  float u1 = u.x, u2 = u.y;
  if (rt_env_split(prm) && (li == prm.sunLight || li == prm.skyLight)) {
    int first = min(prm.sunLight, prm.skyLight);
    float e0 = first > 0 ? cdf[first - 1] : 0.0f;
    float t = rt_rescale(u.z, e0, cdf[first + 1] - e0);
    li = t < (float)q / (float)RT_SHARE_ONE ? prm.sunLight : prm.skyLight;
  }
#else
  int li = rt_pick_light(cdf, prm.numLights, u.x);
  float c0 = li > 0 ? cdf[li - 1] : 0.0f, width = cdf[li] - c0;
  float t = rt_rescale(u.x, c0, width);
  if (rt_env_split(prm) && (li == prm.sunLight || li == prm.skyLight)) {
    /* The place in the environment's interval, divided again by the sun's share. */
    int first = min(prm.sunLight, prm.skyLight);
    float e0 = first > 0 ? cdf[first - 1] : 0.0f;
    width = cdf[first + 1] - e0;
    t = rt_rescale(u.x, e0, width);
    float fs = (float)q / (float)RT_SHARE_ONE;
    if (t < fs) {
      li = prm.sunLight;
      width *= fs;
      t = t / fs;
    } else {
      li = prm.skyLight;
      width *= 1.0f - fs;
      t = (t - fs) / (1.0f - fs);
    }
  }
  float u1 = width >= 1.0f / 4096.0f ? clamp(t, 0.0f, 0x1.fffffep-1f) : u.z;
  float u2 = u.y;
#endif
  RtLight l = lights[li];
  *type = l.type;
  *le = l.radiance.xyz;
  *delta = 0;
  if (l.type >= RT_LIGHT_POINT && l.type <= RT_LIGHT_AREA) {
    float dist = 0.0f;
    float pdf = rt_lamp_sample(l, p, u1, u2, wi, &dist, le, delta);
    *tmax = (l.tri & RT_LAMP_NO_SHADOW) ? 0.0f : dist * (1.0f - 1e-3f);
    return l.select * pdf;
  }
  if (l.type == RT_LIGHT_TRIANGLE) {
    __global const RtTri *t = &tris[l.tri];
    float2 b = rt_sample_triangle(u1, u2);
    float3 q = t->v0.xyz + b.x * t->e1.xyz + b.y * t->e2.xyz;
    float3 nl = normalize(cross(t->e1.xyz, t->e2.xyz));
    float3 v = q - p;
    float dist2 = dot(v, v);
    float dist = sqrt(dist2);
    *wi = v / dist;
    float cosL = -dot(nl, *wi);
    if (cosL <= 0.0f || dist <= 0.0f)
      return 0.0f;
    *tmax = dist * (1.0f - 1e-3f);
    return l.select * dist2 / (l.area * cosL);
  }
  *tmax = INFINITY;
  if (l.type == RT_LIGHT_ENV)
    return l.select * rt_env_sample(envMap, prm, l, u1, u2, wi, le);
  if (l.type == RT_LIGHT_SUN) {
    *wi = rt_to_world(rt_sample_cone(u1, u2, l.dir.w), l.dir.xyz);
    return rt_sun_select(lights, prm, q) / (2.0f * RT_PI * (1.0f - l.dir.w));
  }
  *wi = rt_to_world(rt_sample_cosine(u1, u2), n);
  return rt_sky_select(lights, prm, q) * fmax(dot(*wi, n), 0.0f) * RT_INV_PI;
}

__kernel void shade(__global const RtTri *tris, __global const RtTriAttr *triAttrs,
                    __global const RtMesh *meshes, __global const RtMaterial *materials,
                    __global const RtBsdfNode *bsdfs, __global const RtLight *lights,
                    __global const float *lightCdf, __global const RtShadeParams *params,
                    __global RtPath *paths, __global const int *active, int numActive,
                    __global const RtHit *hits, __global const float4 *outputs, int maxOutputs,
                    __global RtShadowRay *shadowRays, __global uint *counters,
                    __global const float *envMap) {
  int i = get_global_id(0);
  if (i >= numActive)
    return;
  RtShadeParams prm = *params;
  int pid = active[i];
  RtPath p = paths[pid];
  RtHit h = hits[i];
  float3 d = p.dir.xyz;
  float bsdfPdf = p.dir.w;
  int specular = (p.flags & RT_PATH_SPECULAR) != 0;
  float3 thr = p.throughput.xyz;
  shadowRays[i].contrib = (float4)(0.0f);
  p.flags &= ~RT_PATH_ALIVE;

  /* The lamps this segment crosses, up to the surface it hits (or all the way): a lamp is
   * transparent, so the path goes on to that surface (Cycles' shade_light). A BSDF sample's
   * radiance is MIS-weighted against next-event estimation's pdf for the same direction. */
  for (int k = 0; k < prm.numLamps; ++k) {
    RtLight l = lights[prm.lampFirst + k];
    if (p.depth == 1 && !(l.tri & RT_LAMP_CAMERA))
      continue;
    float lpdf;
    float3 le = rt_lamp_hit(l, p.origin.xyz, d, h.tri < 0 ? INFINITY : h.t, &lpdf);
    if (rt_max3(le) > 0.0f) {
      float w = specular ? 1.0f : rt_mis(bsdfPdf, l.select * lpdf);
      p.radiance.xyz += thr * le * w * RT_KEEP(RT_SPLIT_LAMP, p.depth);
    }
  }

  if (h.tri < 0) {
    p.radiance.xyz += thr * rt_environment(lights, prm, envMap, d, bsdfPdf, p.radiance.w,
                                           (uint)p.flags >> 16, specular, p.depth);
    paths[pid] = p;
    return;
  }
  RtSurface s = rt_surface(tris, triAttrs, p.origin.xyz, d, h);
  RtTriAttr ta = triAttrs[h.tri];
  RtMesh mesh = meshes[ta.mesh];
  if (s.front && rt_max3(mesh.emission.xyz) > 0.0f) {
    float w = 1.0f;
    if (!specular && ta.light >= 0) {
      RtLight l = lights[ta.light];
      float cosL = -dot(s.ng, d);
      float lp = l.select * h.t * h.t / (l.area * fmax(cosL, 1e-8f));
      w = rt_mis(bsdfPdf, lp);
    }
    p.radiance.xyz += thr * mesh.emission.xyz * w * RT_KEEP(RT_SPLIT_MESH, p.depth);
  }

  /* Choose a leaf of the BSDF tree. */
  uint rng = p.rng;
  int base = i * maxOutputs;
  int node = materials[mesh.material].root;
  uint sample = as_uint(p.origin.w), key = as_uint(p.throughput.w);
  /* One sampler number for the whole tree: each blend's choice rescales it into [0, 1) for
   * the next, so the choices stay stratified. */
  float ub = 0.0f;
  for (int guard = 0; guard < 32 && bsdfs[node].type == RT_BSDF_BLEND; ++guard) {
    float m = rt_input(bsdfs[node].in[0], outputs, base).x;
    if (!isfinite(m)) {
      rt_poison(paths, pid, p, rng);
      return;
    }
    m = clamp(m, 0.0f, 1.0f);
#ifdef RT_SAMPLER_PCG
    ub = rt_rand(&rng);
#else
    if (guard == 0)
      ub = rt_sobol1d(sample, rt_pattern_seed(key, RT_PATTERN_BLEND(p.depth)));
#endif
    if (ub < m) {
      node = bsdfs[node].b;
      ub = fmin(ub / m, 0x1.fffffep-1f);
    } else {
      node = bsdfs[node].a;
      ub = fmin((ub - m) / (1.0f - m), 0x1.fffffep-1f);
    }
  }
  RtBsdfNode leaf = bsdfs[node];
  float3 color = rt_input(leaf.in[RT_IN_COLOR], outputs, base).xyz;
  float param = rt_input(leaf.in[RT_IN_ROUGHNESS], outputs, base).x;
  if (!rt_finite3(color) || !isfinite(param)) {
    rt_poison(paths, pid, p, rng);
    return;
  }
  color = fmax(color, (float3)(0.0f));
  if (leaf.type == RT_BSDF_EMISSION) {
    p.radiance.xyz += thr * color * param * RT_KEEP(RT_SPLIT_MATERIAL, p.depth);
    p.rng = rng;
    paths[pid] = p;
    return;
  }
  RtPrincipled pr;
  pr.base = color;
  pr.roughness = param;
  pr.metallic = pr.f0 = 0.0f;
  pr.bumped = 0;
  pr.nSmooth = s.ns;
  if (leaf.type == RT_BSDF_PRINCIPLED) {
    pr.metallic = rt_input(leaf.in[RT_IN_METALLIC], outputs, base).x;
    float spec = rt_input(leaf.in[RT_IN_SPECULAR], outputs, base).x;
    float3 ec = rt_input(leaf.in[RT_IN_EMISSION_COLOR], outputs, base).xyz;
    float es = rt_input(leaf.in[RT_IN_EMISSION_STRENGTH], outputs, base).x;
    if (!isfinite(pr.metallic) || !isfinite(spec) || !rt_finite3(ec) || !isfinite(es)) {
      rt_poison(paths, pid, p, rng);
      return;
    }
    pr.metallic = clamp(pr.metallic, 0.0f, 1.0f);
    pr.f0 = clamp(0.08f * spec, 0.0f, 1.0f);
    pr.base = fmin(color, (float3)(1.0f));
    if (es > 0.0f)
      p.radiance.xyz += thr * fmax(ec, (float3)(0.0f)) * es * RT_KEEP(RT_SPLIT_MATERIAL, p.depth);
  }
  /* A shading normal from the material (a bump node): kept on the side of the geometric
   * normal, and tilted towards it so that it is at least a little above the surface. */
  /* The smooth normal before the bump: a bumped diffuse leaf, and a bumped principled's
   * diffuse base, are shadowed against it as Cycles' bump map correction (on by default)
   * does (rt_bump_shadowing). */
  float3 nSmooth = s.ns;
  int bumped = 0;
  if (leaf.in[RT_IN_NORMAL].output >= 0) {
    bumped = 1;
    float3 nb = rt_input(leaf.in[RT_IN_NORMAL], outputs, base).xyz;
    if (!rt_finite3(nb)) {
      rt_poison(paths, pid, p, rng);
      return;
    }
    float len = length(nb);
    if (len > 0.0f) {
      nb /= len;
      float c = dot(nb, s.ng);
      if (c < 0.01f)
        nb = normalize(nb + (0.01f - c) * s.ng);
      s.ns = nb;
    }
  }
  pr.bumped = bumped;
  float3 wo = -d;
  /* A glossy leaf's normal lifted so that its mirror reflection stays above the surface, as
   * Cycles' Glossy BSDF does (rt_valid_reflection_normal). */
  if (leaf.type == RT_BSDF_GLOSSY)
    s.ns = rt_valid_reflection_normal(s.ng, wo, s.ns);
  /* A principled leaf's GGX lobes lift theirs the same way; its diffuse base keeps s.ns. */
  pr.nSpec = leaf.type == RT_BSDF_PRINCIPLED ? rt_valid_reflection_normal(s.ng, wo, s.ns) : s.ns;
  RtPrincipledAtWo prw;
  if (leaf.type == RT_BSDF_PRINCIPLED)
    prw = rt_principled_at_wo(pr, wo);
  int canExtend = prm.maxDepth < 0 || p.depth + 1 <= prm.maxDepth;
  uint sunShare = canExtend ? rt_sun_share(lights, prm, s.ns) : 0u;

  /* Next-event estimation. */
  if (canExtend && prm.numLights > 0 && leaf.type != RT_BSDF_MIRROR) {
    float3 wi, le;
    float tmax;
    int type, delta;
    float choice = RT_SAMPLE1(&rng, sample, rt_pattern_seed(key, RT_PATTERN_LIGHT_CHOICE(p.depth)));
    float2 lu = RT_SAMPLE2(&rng, sample, rt_pattern_seed(key, RT_PATTERN_LIGHT(p.depth)));
    float3 u = (float3)(lu, choice);
    float lp = rt_sample_light(lights, lightCdf, tris, envMap, prm, s.p, s.ns, sunShare, u, &wi,
                               &tmax, &le, &type, &delta);
    if (lp > 0.0f && dot(wi, s.ng) > 0.0f) {
      float bp;
      float3 f = leaf.type == RT_BSDF_PRINCIPLED
                     ? rt_principled_eval(pr, prw, s.ns, wo, wi, &bp)
                     : rt_bsdf_eval(leaf.type, color, param, s.ns, wo, wi, &bp);
      /* rt_principled_eval's f includes its lobes' cosines (to their own normals). */
      float cosI = leaf.type == RT_BSDF_PRINCIPLED ? 1.0f : dot(wi, s.ns);
      if (bumped && leaf.type == RT_BSDF_DIFFUSE)
        f *= rt_bump_shadowing(nSmooth, s.ns, wi);
      float3 c = thr * f * le * (cosI * (delta ? 1.0f : rt_mis(lp, bp)) / lp);
#ifdef RT_SPLIT_LIGHTS
      c *= RT_KEEP(type == RT_LIGHT_TRIANGLE ? RT_SPLIT_MESH
                   : type == RT_LIGHT_SUN    ? RT_SPLIT_SUN
                   : type == RT_LIGHT_SKY || type == RT_LIGHT_ENV ? RT_SPLIT_SKY
                                             : RT_SPLIT_LAMP,
                   p.depth + 1);
#endif
      if (!rt_finite3(c)) {
        rt_poison(paths, pid, p, rng);
        return;
      }
      if (rt_max3(c) > 0.0f) {
        RtShadowRay r;
        r.origin = (float4)(rt_offset(s, wi, prm.epsilon), 0.0f);
        r.dir = (float4)(wi, tmax);
        r.contrib = (float4)(c, 1.0f);
        shadowRays[i] = r;
        atomic_inc(&counters[RT_COUNT_SHADOW_RAYS]);
      }
    }
  }

  /* The next direction. */
  if (canExtend) {
    float3 wi;
    float pdf;
    int delta;
    float2 bu = RT_SAMPLE2(&rng, sample, rt_pattern_seed(key, RT_PATTERN_BSDF(p.depth)));
    float u1 = bu.x, u2 = bu.y;
    float3 wgt = (float3)(0.0f);
    if (leaf.type == RT_BSDF_PRINCIPLED) {
      delta = 0;
      wgt = rt_principled_sample(pr, prw, s.ns, wo, u1, u2, &wi, &pdf);
    } else {
      wgt = rt_bsdf_sample(leaf.type, color, param, s.ns, wo, u1, u2, &wi, &pdf, &delta);
      if (bumped && leaf.type == RT_BSDF_DIFFUSE)
        wgt *= rt_bump_shadowing(nSmooth, s.ns, wi);
    }
    if (!rt_finite3(wgt)) {
      rt_poison(paths, pid, p, rng);
      return;
    }
    if (rt_max3(wgt) > 0.0f && dot(wi, s.ng) > 0.0f) {
      thr *= wgt;
      int alive = 1;
      if (p.depth >= prm.rrDepth) {
        float q = fmin(rt_max3(thr), 0.95f);
        if (rt_rand(&rng) >= q)
          alive = 0;
        else
          thr /= q;
      }
      if (alive) {
        p.origin = (float4)(rt_offset(s, wi, prm.epsilon), as_float(sample));
        p.dir = (float4)(wi, delta ? -1.0f : pdf);
        p.throughput = (float4)(thr, as_float(key));
        p.radiance.w = delta ? 0.0f : rt_sky_pdf(lights, prm, s.ns, sunShare, wi);
        p.flags = RT_PATH_ALIVE | (delta ? RT_PATH_SPECULAR : 0) | (int)(sunShare << 16);
        p.depth += 1;
      }
    }
  }
  p.rng = rng;
  paths[pid] = p;
}
