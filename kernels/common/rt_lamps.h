/* rt_lamps.h: Blender's point, spot and area lamps with Cycles' conventions (docs/scene.md):
 * next-event estimation samples a point on the lamp, and every path segment adds the radiance
 * of the lamps it crosses. Lamps are not geometry: they cast no shadow on each other and paths
 * go on through them (Cycles treats a lamp as a transparent surface). With Cycles' default
 * soft falloff, a point or spot lamp of radius r is a disk of radius r facing the point it
 * lights (a different disk for every point); of radius 0 it is a true point (a delta light,
 * which no ray hits); with Soft Falloff off (RT_LAMP_SPHERE) it is a sphere of radius r. An
 * area lamp is a one-sided rectangle or ellipse. OpenCL C 1.2. */
#ifndef RT_LAMPS_H
#define RT_LAMPS_H

#include "rt_sampling.h"
#include "rt_types.h"

/* Smoothstep on [0, 1], 0 below (and for NaN), 1 above. */
static inline float rt_smoothstep01(float x) {
  if (!(x > 0.0f))
    return 0.0f;
  if (x >= 1.0f)
    return 1.0f;
  return x * x * (3.0f - 2.0f * x);
}

/* A spot's factor along w (a unit vector from the lamp towards the lit point): Cycles'
 * smoothstep((cos - cos(half angle)) / ((1 - cos(half angle)) * blend)); no cosine falloff
 * inside the cone, and no renormalization of the power to the cone. */
static inline float rt_spot_factor(RtLight l, float3 w) {
  return rt_smoothstep01((dot(w, l.dir.xyz) - l.dir.w) * l.u.w);
}

/* A uniform point of the unit disk through the concentric map (Shirley and Chiu 1997), so
 * that stratified (u1, u2) stay stratified on the disk. */
static inline float2 rt_sample_disk(float u1, float u2) {
  float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  if (a == 0.0f && b == 0.0f)
    return (float2)(0.0f);
  float r, phi;
  if (a * a > b * b) {
    r = a;
    phi = 0.25f * RT_PI * (b / a);
  } else {
    r = b;
    phi = 0.5f * RT_PI - 0.25f * RT_PI * (a / b);
  }
  return (float2)(r * cos(phi), r * sin(phi));
}

/* The nearest t in (0, tmax) where the ray o + t d (unit d) meets the sphere of centre c and
 * radius r (from inside: where it leaves it); -1 if none. */
static inline float rt_sphere_hit(float3 o, float3 d, float3 c, float r, float tmax) {
  float3 oc = o - c;
  float b = dot(oc, d);
  float cc = dot(oc, oc) - r * r;
  float disc = b * b - cc;
  if (!(disc >= 0.0f))
    return -1.0f;
  float sq = sqrt(disc);
  float t = -b - sq;
  if (!(t > 0.0f))
    t = -b + sq;
  return t > 0.0f && t < tmax ? t : -1.0f;
}

/* A sphere lamp (a point or spot with Soft Falloff off, Cycles' is_sphere): from outside,
 * directions uniform in the cone the sphere subtends; from inside, uniform on the sphere of
 * directions (Cycles' choice for a surface with transmission; the same image). The
 * solid-angle pdf of d from o, as rt_lamp_sample draws it. */
static inline float rt_sphere_pdf(RtLight l, float3 o) {
  float3 v = o - l.pos.xyz;
  float d2 = dot(v, v), r2 = l.pos.w * l.pos.w;
  if (d2 <= r2)
    return 1.0f / (4.0f * RT_PI);
  float cosMax = sqrt(fmax(0.0f, 1.0f - r2 / d2));
  /* 1 - cosMax without cancellation: (r2 / d2) / (1 + cosMax) */
  return 1.0f / (2.0f * RT_PI * ((r2 / d2) / (1.0f + cosMax)));
}

/* Samples a point of lamp l seen from p (u1, u2 in [0, 1)): the direction wi, the distance,
 * the radiance le (a delta lamp: its intensity times the spot factor, with *delta = 1) and
 * the solid-angle pdf (a delta lamp: the squared distance, so that le / pdf is the
 * irradiance). 0: no contribution (p behind an area lamp, outside a spot's cone). */
static inline float rt_lamp_sample(RtLight l, float3 p, float u1, float u2, float3 *wi,
                                   float *dist, float3 *le, int *delta) {
  *delta = 0;
  *le = l.radiance.xyz;
  if (l.tri & RT_LAMP_SPHERE) {
    float3 toC = l.pos.xyz - p;
    float d2 = dot(toC, toC), r2 = l.pos.w * l.pos.w;
    int inside = d2 <= r2;
    if (inside) {
      *wi = rt_sample_sphere(u1, u2);
    } else {
      float dc = sqrt(d2);
      float oneMinusCos = (r2 / d2) / (1.0f + sqrt(fmax(0.0f, 1.0f - r2 / d2)));
      float z = 1.0f - u1 * oneMinusCos;
      float s = sqrt(fmax(0.0f, 1.0f - z * z));
      float phi = 2.0f * RT_PI * u2;
      *wi = rt_to_world((float3)(s * cos(phi), s * sin(phi), z), toC / dc);
    }
    float t = rt_sphere_hit(p, *wi, l.pos.xyz, l.pos.w, INFINITY);
    if (!(t > 0.0f))
      t = inside ? 0.0f : sqrt(fmax(0.0f, d2 - r2)); /* grazing: the tangent distance */
    *dist = t;
    if (l.type == RT_LIGHT_SPOT && !inside) {
      float a = rt_spot_factor(l, -*wi);
      if (a <= 0.0f)
        return 0.0f;
      *le *= a;
    }
    return t > 0.0f ? rt_sphere_pdf(l, p) : 0.0f;
  }
  float3 q;
  float3 n; /* the emitting side's normal at q */
  float area;
  if (l.type == RT_LIGHT_AREA) {
    n = l.dir.xyz;
    if (dot(p - l.pos.xyz, n) <= 0.0f)
      return 0.0f; /* behind the lamp or in its plane */
    if (l.tri & RT_LAMP_ELLIPSE) {
      float2 e = rt_sample_disk(u1, u2);
      q = l.pos.xyz + e.x * l.u.xyz + e.y * l.v.xyz;
    } else {
      q = l.pos.xyz + (2.0f * u1 - 1.0f) * l.u.xyz + (2.0f * u2 - 1.0f) * l.v.xyz;
    }
    area = l.area;
  } else {
    float3 toP = p - l.pos.xyz;
    float dc = length(toP);
    if (!(dc > 0.0f))
      return 0.0f;
    n = toP / dc; /* the disk faces p */
    float r = l.pos.w;
    q = l.pos.xyz;
    if (r > 0.0f) {
      float3 t, b;
      rt_frame(n, &t, &b);
      float2 e = rt_sample_disk(u1, u2);
      q += r * (e.x * t + e.y * b);
    }
    area = RT_PI * r * r;
  }
  float3 v = q - p;
  float d2 = dot(v, v);
  float d = sqrt(d2);
  if (!(d > 0.0f))
    return 0.0f;
  *wi = v / d;
  *dist = d;
  if (l.type == RT_LIGHT_SPOT) {
    float a = rt_spot_factor(l, -*wi);
    if (a <= 0.0f)
      return 0.0f;
    *le *= a;
  }
  if (l.type != RT_LIGHT_AREA && l.pos.w <= 0.0f) {
    *delta = 1;
    return d2;
  }
  float c = -dot(n, *wi);
  if (c <= 0.0f)
    return 0.0f;
  return d2 / (area * c);
}

/* The radiance of lamp l where the ray o + t d (unit d, 0 < t < tmax) crosses it, and in *pdf
 * the solid-angle pdf with which rt_lamp_sample picks d from o (for MIS); 0 if it does not
 * cross it (a delta lamp, the back of an area lamp, a spot seen from behind or outside its
 * cone). */
static inline float3 rt_lamp_hit(RtLight l, float3 o, float3 d, float tmax, float *pdf) {
  *pdf = 0.0f;
  float3 none = (float3)(0.0f);
  if (l.type == RT_LIGHT_AREA) {
    float3 n = l.dir.xyz;
    float dn = dot(d, n);
    if (!(dn < 0.0f))
      return none; /* one-sided */
    float t = dot(l.pos.xyz - o, n) / dn;
    if (!(t > 0.0f && t < tmax))
      return none;
    float3 h = o + t * d - l.pos.xyz;
    float x = dot(h, l.u.xyz) / dot(l.u.xyz, l.u.xyz);
    float y = dot(h, l.v.xyz) / dot(l.v.xyz, l.v.xyz);
    int inside = (l.tri & RT_LAMP_ELLIPSE) ? x * x + y * y <= 1.0f
                                            : fabs(x) <= 1.0f && fabs(y) <= 1.0f;
    if (!inside)
      return none;
    *pdf = t * t / (l.area * -dn);
    return l.radiance.xyz;
  }
  float r = l.pos.w;
  if (!(r > 0.0f))
    return none;
  float3 toO = o - l.pos.xyz;
  if (l.tri & RT_LAMP_SPHERE) {
    /* A spot's sphere is one-sided as Cycles': only rays heading towards its centre. */
    if (l.type == RT_LIGHT_SPOT && !(dot(d, toO) < 0.0f))
      return none;
    float t = rt_sphere_hit(o, d, l.pos.xyz, r, tmax);
    if (!(t > 0.0f))
      return none;
    float3 le = l.radiance.xyz;
    if (l.type == RT_LIGHT_SPOT && dot(toO, toO) > r * r) {
      float a = rt_spot_factor(l, -d);
      if (a <= 0.0f)
        return none;
      le *= a;
    }
    *pdf = rt_sphere_pdf(l, o);
    return le;
  }
  float dc = length(toO);
  if (!(dc > 0.0f))
    return none;
  float3 n = toO / dc; /* the disk facing the ray's origin */
  float dn = dot(d, n);
  if (!(dn < 0.0f))
    return none;
  float t = dc / -dn;
  if (!(t < tmax))
    return none;
  float3 h = toO + t * d;
  if (dot(h, h) > r * r)
    return none;
  float3 le = l.radiance.xyz;
  if (l.type == RT_LIGHT_SPOT) {
    float a = rt_spot_factor(l, -d);
    if (a <= 0.0f)
      return none;
    le *= a;
  }
  *pdf = t * t / (RT_PI * r * r * -dn);
  return le;
}

#endif
