/* rt_env.h: the world as an equirectangular environment map (scene.json's "environment" light,
 * docs/scene.md) with Cycles' conventions: a world direction d is looked up at e = M d (M the
 * light's rotation: rows in dir, pos and u), at Cycles' equirectangular coordinates
 * u = 0.5 - atan2(e.y, e.x) / 2pi, v = 1 - acos(e.z) / pi (v = 0 the image's bottom row, the
 * image's centre looks along +x, its top along +z), interpolated as Cycles' Environment Texture
 * node does (Linear: bilinear between texel centres, wrapping in both axes, as Cycles'
 * periodic extension; Closest: the texel), times the light's radiance (the strength).
 * Next-event estimation samples a direction from a piecewise-constant density over the texels
 * (runtime/lib/Environment.cpp builds it: luminance x sin(theta), each texel's value spread as
 * far as the bilinear lookup spreads it, so that every direction with radiance has density).
 *
 * The envMap buffer: W*H float4 texels, row 0 the bottom row (v = 0), xyz the value that is
 * interpolated (an sRGB image's encoded values: decoded after interpolation, as Cycles reads
 * 8- and 16-bit files), w the texel's density in (u, v); then H floats, the rows' marginal CDF;
 * then W*H floats, each row's conditional CDF. OpenCL C 1.2. */
#ifndef RT_ENV_H
#define RT_ENV_H

#include "rt_sampling.h"
#include "rt_types.h"

static inline float3 rt_env_texel(__global const float *env, int w, int h, int x, int y) {
  x %= w;
  if (x < 0)
    x += w;
  y %= h;
  if (y < 0)
    y += h;
  return vload4(y * w + x, env).xyz;
}

/* Cycles' equirectangular coordinates of a unit direction e (in the map's space). */
static inline float2 rt_env_uv(float3 e) {
  float u = 0.5f - atan2(e.y, e.x) * (0.5f * RT_INV_PI);
  float v = 1.0f - acos(clamp(e.z, -1.0f, 1.0f)) * RT_INV_PI;
  return (float2)(u, v);
}

/* The map's value at (u, v), before the strength. */
static inline float3 rt_env_lookup(__global const float *env, RtShadeParams prm, float2 uv) {
  const int w = prm.envWidth, h = prm.envHeight;
  float3 c;
  if (prm.envFlags & RT_ENV_CLOSEST) {
    c = rt_env_texel(env, w, h, (int)floor(uv.x * (float)w), (int)floor(uv.y * (float)h));
  } else {
    const float fx = uv.x * (float)w - 0.5f, fy = uv.y * (float)h - 0.5f;
    const float x0f = floor(fx), y0f = floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = (int)x0f, y0 = (int)y0f;
    c = mix(mix(rt_env_texel(env, w, h, x0, y0), rt_env_texel(env, w, h, x0 + 1, y0), tx),
            mix(rt_env_texel(env, w, h, x0, y0 + 1), rt_env_texel(env, w, h, x0 + 1, y0 + 1), tx),
            ty);
  }
  if (prm.envFlags & RT_ENV_SRGB) {
    const float3 v = c;
    c = select(pow((v + 0.055f) / 1.055f, (float3)(2.4f)), v / 12.92f,
               isless(v, (float3)(0.04045f)));
    c = select(c, (float3)(0.0f), isless(v, (float3)(0.0f)));
  }
  return c;
}

/* The map's space from the world's (M d) and back (M^T e). */
static inline float3 rt_env_to_map(RtLight l, float3 d) {
  return (float3)(dot(l.dir.xyz, d), dot(l.pos.xyz, d), dot(l.u.xyz, d));
}

static inline float3 rt_env_to_world(RtLight l, float3 e) {
  return e.x * l.dir.xyz + e.y * l.pos.xyz + e.z * l.u.xyz;
}

/* The radiance arriving along the world direction d (unit). */
static inline float3 rt_env_radiance(__global const float *env, RtShadeParams prm, RtLight l,
                                     float3 d) {
  return rt_env_lookup(env, prm, rt_env_uv(rt_env_to_map(l, d))) * l.radiance.xyz;
}

/* The solid-angle density with which rt_env_sample draws the world direction d. */
static inline float rt_env_pdf(__global const float *env, RtShadeParams prm, RtLight l,
                               float3 d) {
  const int w = prm.envWidth, h = prm.envHeight;
  const float3 e = rt_env_to_map(l, d);
  const float st = sqrt(fmax(0.0f, 1.0f - e.z * e.z));
  if (!(st > 0.0f))
    return 0.0f;
  const float2 uv = rt_env_uv(e);
  const int x = clamp((int)floor(uv.x * (float)w), 0, w - 1);
  const int y = clamp((int)floor(uv.y * (float)h), 0, h - 1);
  return vload4(y * w + x, env).w / (2.0f * RT_PI * RT_PI * st);
}

/* The first k of [0, n) with u < cdf[k] (n - 1 if none). */
static inline int rt_env_search(__global const float *cdf, int n, float u) {
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (u < cdf[mid])
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

/* Where u falls inside [c0, c1), in [0, 1). */
static inline float rt_env_within(float u, float c0, float c1) {
  return c1 > c0 ? clamp((u - c0) / (c1 - c0), 0.0f, 0x1.fffffep-1f) : 0.5f;
}

/* Draws a world direction *wi (u1 the column's number, u2 the row's) with the radiance *le
 * arriving along it; returns its solid-angle density (0: none). */
static inline float rt_env_sample(__global const float *env, RtShadeParams prm, RtLight l,
                                  float u1, float u2, float3 *wi, float3 *le) {
  const int w = prm.envWidth, h = prm.envHeight;
  __global const float *marginal = env + 4 * w * h;
  const int y = rt_env_search(marginal, h, u2);
  const float fy = rt_env_within(u2, y > 0 ? marginal[y - 1] : 0.0f, marginal[y]);
  __global const float *row = marginal + h + y * w;
  const int x = rt_env_search(row, w, u1);
  const float fx = rt_env_within(u1, x > 0 ? row[x - 1] : 0.0f, row[x]);
  const float2 uv = (float2)(((float)x + fx) / (float)w, ((float)y + fy) / (float)h);
  const float theta = RT_PI * (1.0f - uv.y), phi = RT_PI * (1.0f - 2.0f * uv.x);
  const float st = sin(theta);
  if (!(st > 0.0f))
    return 0.0f;
  *wi = rt_env_to_world(l, (float3)(st * cos(phi), st * sin(phi), cos(theta)));
  *le = rt_env_lookup(env, prm, uv) * l.radiance.xyz;
  return vload4(y * w + x, env).w / (2.0f * RT_PI * RT_PI * st);
}

#endif
