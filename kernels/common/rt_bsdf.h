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

/* Smith's Lambda of GGX at a direction of cosine c to the normal. */
static inline float rt_ggx_lambda(float c, float a2) {
  return 0.5f * (sqrt(1.0f + a2 * fmax(1.0f / (c * c) - 1.0f, 0.0f)) - 1.0f);
}

/* The height-correlated masking-shadowing of both directions, as Cycles' microfacet
 * closures take it: 1 / (1 + Lambda(wi) + Lambda(wo)). */
static inline float rt_ggx_g2(float cosI, float cosO, float a2) {
  return 1.0f / (1.0f + rt_ggx_lambda(cosI, a2) + rt_ggx_lambda(cosO, a2));
}

static inline float3 rt_schlick(float3 f0, float cosD) {
  float m = 1.0f - clamp(cosD, 0.0f, 1.0f);
  float m5 = m * m * m * m * m;
  return f0 + (1.0f - f0) * m5;
}

/* rt_ggx_albedo.h's tables: node i of an axis of n nodes at i / (n - 1), linear between. */
static inline float rt_ggx_lookup1(__constant const float *t, float x, int n) {
  x = clamp(x, 0.0f, 1.0f) * (float)(n - 1);
  int i = min((int)x, n - 1);
  return mix(t[i], t[min(i + 1, n - 1)], x - (float)i);
}

static inline float rt_ggx_lookup2(__constant const float *t, float x, float y, int n) {
  y = clamp(y, 0.0f, 1.0f) * (float)(n - 1);
  int j = min((int)y, n - 1);
  return mix(rt_ggx_lookup1(t + j * n, x, n), rt_ggx_lookup1(t + min(j + 1, n - 1) * n, x, n),
             y - (float)j);
}

static inline float rt_ggx_lookup3(__constant const float *t, float x, float y, float z, int n) {
  z = clamp(z, 0.0f, 1.0f) * (float)(n - 1);
  int k = min((int)z, n - 1);
  return mix(rt_ggx_lookup2(t + k * n * n, x, y, n),
             rt_ggx_lookup2(t + min(k + 1, n - 1) * n * n, x, y, n), z - (float)k);
}

/* The multiple-scattering factor of a GGX lobe at wo, as Cycles' energy-preserving GGX scales
 * it: 1 + F_ms (1 - E) / E, with E the lobe's single-scattering albedo at wo, and F_ms =
 * F_ss E_avg / (1 - F_ss (1 - E_avg)) the multiple-bounce Fresnel of a lobe whose mean
 * Fresnel over the hemisphere is F_ss (Kulla and Conty 2017, one F_ss cancelled: the single
 * scattering already has one bounce of Fresnel). */
typedef struct RtGgxEnergy {
  float missing; /* (1 - E) / E */
  float eavg;
} RtGgxEnergy;

static inline RtGgxEnergy rt_ggx_energy(float roughness, float cosO) {
  RtGgxEnergy g;
  float r = clamp(roughness, 0.0f, 1.0f);
  float e = fmax(rt_ggx_lookup2(rt_ggx_e, r, cosO, 32), 1e-3f);
  g.missing = (1.0f - e) / e;
  g.eavg = rt_ggx_lookup1(rt_ggx_eavg, r, 32);
  return g;
}

static inline float3 rt_ggx_ms_scale(RtGgxEnergy g, float3 fss) {
  float3 fms = fss * g.eavg / ((float3)(1.0f) - fss * (1.0f - g.eavg));
  return (float3)(1.0f) + fms * g.missing;
}

/* D G2 / (4 cos wi cos wo) of a GGX lobe (no Fresnel) and the pdf of sampling wi by its normal
 * distribution (D cos h / (4 wo.h)); 0 when wi or wo is below n or h is invalid. */
static inline float rt_ggx_lobe(float3 n, float3 wo, float3 wi, float a2, float *pdf,
                                float *cosD) {
  float cosI = dot(wi, n), cosO = dot(wo, n);
  *pdf = 0.0f;
  *cosD = 0.0f;
  if (cosI <= 0.0f || cosO <= 0.0f)
    return 0.0f;
  float3 h = normalize(wi + wo);
  float cosH = dot(h, n);
  *cosD = dot(wi, h);
  if (cosH <= 0.0f || *cosD <= 0.0f)
    return 0.0f;
  float d = rt_ggx_d(cosH, a2);
  *pdf = d * cosH / (4.0f * *cosD);
  return d * rt_ggx_g2(cosI, cosO, a2) / (4.0f * cosI * cosO);
}

/* Samples a half vector about n by GGX's normal distribution and reflects wo about it. */
static inline float3 rt_ggx_sample_dir(float3 n, float3 wo, float a2, float u1, float u2) {
  float cos2 = (1.0f - u1) / (1.0f + u1 * (a2 - 1.0f));
  float cosT = sqrt(fmax(cos2, 0.0f)), sinT = sqrt(fmax(0.0f, 1.0f - cos2));
  float phi = 2.0f * RT_PI * u2;
  float3 h = rt_to_world((float3)(sinT * cos(phi), sinT * sin(phi), cosT), n);
  return 2.0f * dot(wo, h) * h - wo;
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
    float a = rt_ggx_alpha(roughness);
    float cosD;
    float dg = rt_ggx_lobe(n, wo, wi, a * a, pdf, &cosD);
    /* Blender's Glossy BSDF (Multiscatter GGX): no Fresnel (the colour is the reflectance at
     * every angle), the energy single-scattering GGX loses given back as Cycles' energy-
     * preserving GGX does for a constant Fresnel of the colour (rt_ggx_ms_scale). */
    return dg > 0.0f ? color * rt_ggx_ms_scale(rt_ggx_energy(roughness, cosO), color) * dg
                     : (float3)(0.0f);
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
    *wi = rt_ggx_sample_dir(n, wo, a * a, u1, u2);
    float3 f = rt_bsdf_eval(type, color, roughness, n, wo, *wi, pdf);
    if (*pdf <= 0.0f)
      return (float3)(0.0f);
    return f * dot(*wi, n) / *pdf;
  }
  *pdf = 0.0f;
  return (float3)(0.0f);
}

/* The Principled subset as Cycles' Principled BSDF builds it (without transmission, coat,
 * sheen, subsurface, anisotropy, thin film; specular tint white; diffuse roughness 0), layers
 * weighted by metallic m:
 *   metal (weight m): GGX with Schlick Fresnel of F0 = baseColor (F82 tint white is Schlick);
 *   dielectric (weight 1 - m): a GGX specular layer over a Lambertian base. The layer's
 *     reflectance at normal incidence is f0 = 0.08 x specular (IOR level; 0.5: IOR 1.5, F0
 *     0.04) and its Fresnel is the real dielectric Fresnel of IOR eta = ior(f0), rescaled to
 *     run from f0 to 1 (Cycles' generalized Schlick with a negative exponent); f0 = 0 leaves
 *     no layer. The base is weighted by 1 - the layer's estimated albedo at wo (Cycles'
 *     closure layering: f0 + (1 - f0) S from rt_ggx_s_ior, times the layer's multiple-bounce
 *     darkening), which is not exactly what the layer reflects: Cycles' furnace is not exactly
 *     1, and neither is this.
 * Both GGX lobes have alpha = roughness^2, the height-correlated G2, and Cycles' multiple-
 * scattering scale (rt_ggx_ms_scale, with the lobe's mean Fresnel F_ss), on the specular
 * normal nSpec (the shading normal lifted so that its mirror reflection of wo stays above the
 * surface, rt_valid_reflection_normal, as Cycles does for these lobes); the diffuse base uses
 * the shading normal. Sampling picks the diffuse base or the GGX lobes by their estimated
 * albedos at wo; the pdf is the mixture's (one-sample MIS over the lobes). */
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
  float3 nSpec;
} RtPrincipled;

static inline float rt_schlick1(float f0, float cosD) {
  float m = 1.0f - clamp(cosD, 0.0f, 1.0f);
  float m5 = m * m * m * m * m;
  return f0 + (1.0f - f0) * m5;
}

/* The unpolarized Fresnel reflectance of a dielectric of relative IOR eta (> 1). */
static inline float rt_fresnel_dielectric(float c, float eta) {
  c = fabs(c);
  float g2 = eta * eta - 1.0f + c * c;
  if (g2 <= 0.0f)
    return 1.0f;
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
  return 0.5f * a * a * (1.0f + b * b);
}

/* What principled needs at wo: the lobes' multiple-scattering scales, the dielectric layer's
 * IOR, the base's weight (what the layer does not take) and the lobe choice; shade.cl makes it
 * once per hit for both next-event estimation and the next direction. */
typedef struct RtPrincipledAtWo {
  float eta;      /* of the dielectric layer; 1: no layer */
  float f0Real;   /* ((eta - 1) / (eta + 1))^2 */
  float scaleD;   /* the dielectric layer's multiple-scattering scale */
  float3 scaleM;  /* the metal's */
  float albedoD;  /* the dielectric layer's estimated albedo */
  float diffuseW; /* (1 - metallic) x (1 - albedoD) */
  float pd;       /* the probability of sampling the diffuse base */
} RtPrincipledAtWo;

/* The probability of sampling the diffuse base at wo (the rest: the GGX lobes), by the lobes'
 * estimated albedos. */
static inline float rt_principled_pdiffuse(RtPrincipled P, RtPrincipledAtWo w, float3 wo) {
  float3 fm = rt_schlick(P.base, dot(wo, P.nSpec));
  float wd = w.diffuseW * (P.base.x + P.base.y + P.base.z) / 3.0f;
  float ws = (1.0f - P.metallic) * w.albedoD + P.metallic * (fm.x + fm.y + fm.z) / 3.0f;
  return wd + ws > 0.0f ? wd / (wd + ws) : 0.5f;
}

static inline RtPrincipledAtWo rt_principled_at_wo(RtPrincipled P, float3 wo) {
  RtPrincipledAtWo w;
  float cosO = dot(wo, P.nSpec);
  RtGgxEnergy g = rt_ggx_energy(P.roughness, cosO);
  float sf0 = sqrt(clamp(P.f0, 0.0f, 0.99f));
  w.eta = (1.0f + sf0) / (1.0f - sf0);
  w.f0Real = sf0 * sf0;
  w.scaleD = 1.0f;
  w.albedoD = 0.0f;
  w.scaleM = (float3)(1.0f);
  if (w.eta > 1.0f && P.metallic < 1.0f) {
    /* The mean Fresnel over the hemisphere (Cycles' fit of a dielectric's, rescaled as the
     * Fresnel is). */
    float fssReal = (w.eta - 1.0f) / (4.08567f + 1.00071f * w.eta);
    float fss = mix(P.f0, 1.0f, clamp((fssReal - w.f0Real) / (1.0f - w.f0Real), 0.0f, 1.0f));
    w.scaleD = rt_ggx_ms_scale(g, (float3)(fss)).x;
    float z = sqrt((w.eta - 1.0f) / (w.eta + 1.0f));
    float s = rt_ggx_lookup3(rt_ggx_s_ior, clamp(P.roughness, 0.0f, 1.0f), cosO, z, 16);
    w.albedoD = w.scaleD / (1.0f + g.missing) * mix(P.f0, 1.0f, s);
  }
  if (P.metallic > 0.0f)
    w.scaleM = rt_ggx_ms_scale(g, mix(P.base, (float3)(1.0f), 1.0f / 21.0f));
  w.diffuseW = (1.0f - P.metallic) * clamp(1.0f - w.albedoD, 0.0f, 1.0f);
  w.pd = rt_principled_pdiffuse(P, w, wo);
  return w;
}

/* f x cos: each lobe's cosine to its own normal (the diffuse base's n, the GGX lobes'
 * nSpec), and the pdf of sampling wi; w = rt_principled_at_wo(P, wo). */
static inline float3 rt_principled_eval(RtPrincipled P, RtPrincipledAtWo w, float3 n, float3 wo,
                                        float3 wi, float *pdf) {
  const float pd = w.pd;
  float cosI = dot(wi, n);
  float3 f = (float3)(0.0f);
  float diffPdf = 0.0f;
  if (cosI > 0.0f) {
    f = P.base * (w.diffuseW * RT_INV_PI * cosI);
    if (P.bumped)
      f *= rt_bump_shadowing(P.nSmooth, n, wi);
    diffPdf = cosI * RT_INV_PI;
  }
  float a = rt_ggx_alpha(P.roughness);
  float specPdf, cosD;
  float dg = rt_ggx_lobe(P.nSpec, wo, wi, a * a, &specPdf, &cosD);
  if (dg > 0.0f) {
    float fd = 0.0f;
    if (w.albedoD > 0.0f) { /* a dielectric layer (metallic < 1, specular > 0) */
      float s = (rt_fresnel_dielectric(cosD, w.eta) - w.f0Real) / (1.0f - w.f0Real);
      fd = mix(P.f0, 1.0f, clamp(s, 0.0f, 1.0f)) * w.scaleD;
    }
    float3 fm = P.metallic > 0.0f ? rt_schlick(P.base, cosD) * w.scaleM : (float3)(0.0f);
    f += ((1.0f - P.metallic) * fd + P.metallic * fm) * (dg * dot(wi, P.nSpec));
  }
  *pdf = pd * diffPdf + (1.0f - pd) * specPdf;
  return f;
}

/* Samples wi; returns (f x cos) / pdf (0 when invalid). */
static inline float3 rt_principled_sample(RtPrincipled P, RtPrincipledAtWo w, float3 n, float3 wo,
                                          float u1, float u2, float3 *wi, float *pdf) {
  *pdf = 0.0f;
  const float pd = w.pd;
  if (u1 < pd) {
    u1 = u1 / pd;
    *wi = rt_to_world(rt_sample_cosine(u1, u2), n);
  } else {
    u1 = (u1 - pd) / (1.0f - pd);
    float a = rt_ggx_alpha(P.roughness);
    *wi = rt_ggx_sample_dir(P.nSpec, wo, a * a, u1, u2);
  }
  float3 f = rt_principled_eval(P, w, n, wo, *wi, pdf);
  if (*pdf <= 0.0f)
    return (float3)(0.0f);
  return f / *pdf;
}

#endif
