/* rt_bsdf.h: the fixed BSDFs (diffuse, GGX glossy as Blender's Glossy BSDF, mirror, the
 * Principled subset) in world space around the shading normal n. eval returns f (without the
 * cosine) and the solid-angle pdf of sampling wi; sample returns wi and the weight
 * f * cos / pdf. OpenCL C 1.2. */
#ifndef RT_BSDF_H
#define RT_BSDF_H

#include "rt_ggx_albedo.h"
#include "rt_sampling.h"
#include "rt_types.h"

/* roughness is perceptual: alpha = roughness^2, kept away from 0 (use `mirror` for a delta). */
static inline float rt_ggx_alpha(float roughness) {
  float r = clamp(roughness, 0.0f, 1.0f);
  return fmax(r * r, 1e-3f);
}

static inline float rt_ggx_d(float cosH, float a2) {
  float c2 = cosH * cosH;
  float den = c2 * (a2 - 1.0f) + 1.0f;
  return a2 / (RT_PI * den * den);
}

static inline float rt_ggx_g1(float cosV, float a2) {
  return 2.0f * cosV / (cosV + sqrt(a2 + (1.0f - a2) * cosV * cosV));
}

static inline float3 rt_schlick(float3 f0, float cosD) {
  float m = 1.0f - clamp(cosD, 0.0f, 1.0f);
  float m5 = m * m * m * m * m;
  return f0 + (1.0f - f0) * m5;
}

/* A table of rt_ggx_albedo.h at (roughness, cos wo), bilinear. */
static inline float rt_ggx_table(__constant const float *t, float roughness, float cosO) {
  const int n = RT_GGX_ALBEDO_N;
  float x = clamp(cosO * n - 0.5f, 0.0f, (float)(n - 1));
  float y = clamp(roughness, 0.0f, 1.0f) * (float)(n - 1);
  int i0 = (int)x, j0 = (int)y;
  int i1 = min(i0 + 1, n - 1), j1 = min(j0 + 1, n - 1);
  float fx = x - (float)i0, fy = y - (float)j0;
  float e0 = mix(t[j0 * n + i0], t[j0 * n + i1], fx);
  float e1 = mix(t[j1 * n + i0], t[j1 * n + i1], fx);
  return mix(e0, e1, fy);
}

/* f and pdf of a non-delta leaf (diffuse or glossy). */
static inline float3 rt_bsdf_eval(int type, float3 color, float roughness, float3 n, float3 wo,
                           float3 wi, float *pdf) {
  float cosI = dot(wi, n), cosO = dot(wo, n);
  *pdf = 0.0f;
  /* Diffuse asks only that the light is above n, as Cycles' diffuse closure does: a bumped
   * or smooth-shaded normal that faces away from the viewer still shades (the bump
   * shadowing, shade.cl, rejects light below the smooth normal). */
  if (type == RT_BSDF_DIFFUSE) {
    if (cosI <= 0.0f)
      return (float3)(0.0f);
    *pdf = cosI * RT_INV_PI;
    return color * RT_INV_PI;
  }
  if (cosI <= 0.0f || cosO <= 0.0f)
    return (float3)(0.0f);
  if (type == RT_BSDF_GLOSSY) {
    float a2 = rt_ggx_alpha(roughness);
    a2 *= a2;
    float3 h = normalize(wi + wo);
    float cosH = dot(h, n), cosD = dot(wi, h);
    if (cosH <= 0.0f || cosD <= 0.0f)
      return (float3)(0.0f);
    float d = rt_ggx_d(cosH, a2);
    *pdf = d * cosH / (4.0f * cosD);
    float g = rt_ggx_g1(cosI, a2) * rt_ggx_g1(cosO, a2);
    /* Blender's Glossy BSDF: no Fresnel (the colour is the reflectance at every angle), the
     * energy single-scattering GGX loses given back as its multiscatter GGX does, scaled by
     * 1 + color (1 - E) / E (E: the lobe's albedo at wo). */
    float e = fmax(rt_ggx_table(rt_ggx_albedo_table, roughness, cosO), 1e-3f);
    return color * (1.0f + color * ((1.0f - e) / e)) * (d * g / (4.0f * cosI * cosO));
  }
  return (float3)(0.0f);
}

/* Cycles' bump shadowing of a diffuse lobe whose normal nb a bump moved off the smooth normal
 * ns: 0 for light below ns, else the GGX masking G1 at wi's angle to ns, of a roughness that
 * grows with the angle between nb and ns (alpha^2 = tan^2 / 8, at most 1); 1 without bump. */
static inline float rt_bump_shadowing(float3 ns, float3 nb, float3 wi) {
  float cosD = dot(ns, nb), cosI = dot(ns, wi);
  if (cosD >= 1.0f)
    return 1.0f;
  if (cosI * cosD * dot(nb, wi) < 0.0f || cosI < 1e-6f)
    return 0.0f;
  if (cosI >= 1.0f)
    return 1.0f;
  float a2 = clamp(0.125f * (1.0f / (cosD * cosD) - 1.0f), 0.0f, 1.0f);
  return rt_ggx_g1(cosI, a2);
}

/* The normal a glossy lobe uses, as Cycles' Glossy BSDF takes it (its bump map correction, on by
 * default): where the mirror reflection of wo about n would leave the surface below a small
 * height t = min(0.9 cos(wo, ng), 0.01) over the geometric normal ng, n is turned towards ng,
 * in the plane of ng and n, just far enough that the reflection has height t. Without it a
 * strongly bumped or smooth-shaded normal that faces away from the viewer makes the lobe
 * black. n itself when n is ng or the reflection is high enough. */
static inline float3 rt_valid_reflection_normal(float3 ng, float3 wo, float3 n) {
  const float iz = dot(wo, ng);
  const float t = fmin(0.9f * iz, 0.01f);
  if (dot(ng, 2.0f * dot(n, wo) * n - wo) >= t || all(n == ng))
    return n;
  /* x: the unit part of n across ng; the new normal is sqrt(1 - z^2) x + z ng, and its
   * reflection's height 2 (n'.wo) z - iz = t gives a quadratic in z^2. */
  float3 x = n - dot(n, ng) * ng;
  const float lx = length(x);
  x = lx > 1e-7f ? x / lx : n;
  const float ix = dot(wo, x);
  const float a = ix * ix + iz * iz;
  const float b = 2.0f * (a + iz * t);
  const float c = (t + iz) * (t + iz);
  const float root = sqrt(fmax(b * b - 4.0f * a * c, 0.0f));
  const float z2 = 0.25f * (ix < 0.0f ? b + root : b - root) / a;
  return sqrt(fmax(1.0f - z2, 0.0f)) * x + sqrt(fmax(z2, 0.0f)) * ng;
}

/* Samples wi for a leaf; returns the weight f*cos/pdf (0 when the sample is invalid). */
static inline float3 rt_bsdf_sample(int type, float3 color, float roughness, float3 n, float3 wo,
                             float u1, float u2, float3 *wi, float *pdf, int *delta) {
  *delta = 0;
  if (type == RT_BSDF_MIRROR) {
    *delta = 1;
    *pdf = 1.0f;
    *wi = 2.0f * dot(wo, n) * n - wo;
    return dot(*wi, n) > 0.0f ? color : (float3)(0.0f);
  }
  if (type == RT_BSDF_DIFFUSE) {
    *wi = rt_to_world(rt_sample_cosine(u1, u2), n);
    *pdf = dot(*wi, n) * RT_INV_PI;
    return *pdf > 0.0f ? color : (float3)(0.0f);
  }
  if (type == RT_BSDF_GLOSSY) {
    float a = rt_ggx_alpha(roughness);
    float a2 = a * a;
    float cos2 = (1.0f - u1) / (1.0f + u1 * (a2 - 1.0f));
    float cosT = sqrt(fmax(cos2, 0.0f)), sinT = sqrt(fmax(0.0f, 1.0f - cos2));
    float phi = 2.0f * RT_PI * u2;
    float3 h = rt_to_world((float3)(sinT * cos(phi), sinT * sin(phi), cosT), n);
    *wi = 2.0f * dot(wo, h) * h - wo;
    float3 f = rt_bsdf_eval(type, color, roughness, n, wo, *wi, pdf);
    if (*pdf <= 0.0f)
      return (float3)(0.0f);
    return f * dot(*wi, n) / *pdf;
  }
  *pdf = 0.0f;
  return (float3)(0.0f);
}

/* The Principled subset (Blender's Principled BSDF without transmission, coat, sheen,
 * subsurface, anisotropy; specular tint white). Two layers mixed by metallic m:
 *   dielectric: a Lambertian base (baseColor) under a GGX specular layer of F0 = 0.08 *
 *     specular (IOR level 0.5: IOR 1.5, F0 0.04), Schlick Fresnel; the base gets what the
 *     specular layer does not reflect at wo, 1 - its albedo (rt_principled_at_wo);
 *   metal: a GGX lobe with Schlick Fresnel of F0 = baseColor (F82 tint white = Schlick).
 * Both specular lobes share one GGX distribution (alpha = roughness^2), so sampling picks the
 * diffuse lobe or the GGX lobe by their estimated albedos at wo, and the pdf is the mixture's
 * (one-sample MIS over the lobes). The energy that single-scattering GGX loses is added back
 * by scaling (rt_ggx_albedo.h's tables), as Cycles' multiscatter GGX keeps it. */
typedef struct RtPrincipled {
  float3 base;
  float roughness;
  float metallic;
  float f0; /* dielectric */
  /* A bump moved the shading normal off the smooth normal nSmooth: the diffuse base is
   * shadowed as Cycles shadows every diffuse closure (rt_bump_shadowing); the specular
   * lobes are not (Cycles' bump map correction softens only diffuse ones). */
  int bumped;
  float3 nSmooth;
} RtPrincipled;

static inline float rt_schlick1(float f0, float cosD) {
  float m = 1.0f - clamp(cosD, 0.0f, 1.0f);
  float m5 = m * m * m * m * m;
  return f0 + (1.0f - f0) * m5;
}

/* What principled needs at wo: the multiple-scattering factor (1 - E) / E of its GGX lobes,
 * and the albedo of its dielectric specular layer (multiple scattering included), which the
 * diffuse base under it does not get. */
typedef struct RtPrincipledAtWo {
  float ms;
  float dielectricAlbedo;
} RtPrincipledAtWo;

static inline RtPrincipledAtWo rt_principled_at_wo(RtPrincipled P, float cosO) {
  RtPrincipledAtWo w;
  float e = fmax(rt_ggx_table(rt_ggx_albedo_table, P.roughness, cosO), 1e-3f);
  float sch = rt_ggx_table(rt_ggx_schlick_table, P.roughness, cosO);
  w.ms = (1.0f - e) / e;
  float favg = P.f0 + (1.0f - P.f0) / 21.0f;
  w.dielectricAlbedo = clamp((P.f0 * (e - sch) + sch) * (1.0f + favg * w.ms), 0.0f, 1.0f);
  return w;
}

/* The probability of sampling the diffuse base at wo (the rest: the GGX lobe). */
static inline float rt_principled_pdiffuse(RtPrincipled P, RtPrincipledAtWo w, float cosO) {
  float3 fm = rt_schlick(P.base, cosO);
  float wd = (1.0f - P.metallic) * (1.0f - w.dielectricAlbedo) *
             (P.base.x + P.base.y + P.base.z) / 3.0f;
  float ws = (1.0f - P.metallic) * w.dielectricAlbedo + P.metallic * (fm.x + fm.y + fm.z) / 3.0f;
  return wd + ws > 0.0f ? wd / (wd + ws) : 0.5f;
}

static inline float3 rt_principled_eval(RtPrincipled P, float3 n, float3 wo, float3 wi,
                                        float *pdf) {
  float cosI = dot(wi, n), cosO = dot(wo, n);
  *pdf = 0.0f;
  if (cosI <= 0.0f || cosO <= 0.0f)
    return (float3)(0.0f);
  RtPrincipledAtWo w = rt_principled_at_wo(P, cosO);
  float pd = rt_principled_pdiffuse(P, w, cosO);
  float dielectric = 1.0f - P.metallic;
  float3 f = P.base * (dielectric * (1.0f - w.dielectricAlbedo) * RT_INV_PI);
  if (P.bumped)
    f *= rt_bump_shadowing(P.nSmooth, n, wi);
  float specPdf = 0.0f;
  float a = rt_ggx_alpha(P.roughness);
  float a2 = a * a;
  float3 h = normalize(wi + wo);
  float cosH = dot(h, n), cosD = dot(wi, h);
  if (cosH > 0.0f && cosD > 0.0f) {
    float d = rt_ggx_d(cosH, a2);
    specPdf = d * cosH / (4.0f * cosD);
    float dg = d * rt_ggx_g1(cosI, a2) * rt_ggx_g1(cosO, a2) / (4.0f * cosI * cosO);
    /* Multiple scattering: each specular lobe scaled by 1 + F_avg (1 - E) / E, with E the
     * lobe's albedo at wo and F_avg Schlick's hemispherical average, F0 + (1 - F0) / 21. */
    float fd = rt_schlick1(P.f0, cosD) * (1.0f + (P.f0 + (1.0f - P.f0) / 21.0f) * w.ms);
    float3 fm = rt_schlick(P.base, cosD) * (1.0f + (P.base + (1.0f - P.base) / 21.0f) * w.ms);
    f += (dielectric * fd + P.metallic * fm) * dg;
  }
  *pdf = pd * cosI * RT_INV_PI + (1.0f - pd) * specPdf;
  return f;
}

static inline float3 rt_principled_sample(RtPrincipled P, float3 n, float3 wo, float u1,
                                          float u2, float3 *wi, float *pdf) {
  *pdf = 0.0f;
  float cosO = dot(wo, n);
  if (cosO <= 0.0f)
    return (float3)(0.0f);
  float pd = rt_principled_pdiffuse(P, rt_principled_at_wo(P, cosO), cosO);
  if (u1 < pd) {
    u1 = u1 / pd;
    *wi = rt_to_world(rt_sample_cosine(u1, u2), n);
  } else {
    u1 = (u1 - pd) / (1.0f - pd);
    float a = rt_ggx_alpha(P.roughness);
    float a2 = a * a;
    float cos2 = (1.0f - u1) / (1.0f + u1 * (a2 - 1.0f));
    float cosT = sqrt(fmax(cos2, 0.0f)), sinT = sqrt(fmax(0.0f, 1.0f - cos2));
    float phi = 2.0f * RT_PI * u2;
    float3 h = rt_to_world((float3)(sinT * cos(phi), sinT * sin(phi), cosT), n);
    *wi = 2.0f * dot(wo, h) * h - wo;
  }
  float3 f = rt_principled_eval(P, n, wo, *wi, pdf);
  if (*pdf <= 0.0f)
    return (float3)(0.0f);
  return f * (dot(*wi, n) / *pdf);
}

#endif
