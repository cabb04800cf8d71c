/* blender/noise.cl: Blender's Noise Texture node (Cycles, Blender 5.0), value for value.
 *
 * Perlin gradient noise on the integer lattice, hashed with Bob Jenkins' lookup3 (the hash
 * Cycles uses, so the lattice gradients are Blender's), scaled to about [-1, 1] per dimension,
 * summed over octaves by one of five fractal types. Detail may be fractional: the last octave is
 * blended in by the fractional part. Distortion displaces the lookup point by noise taken at
 * fixed seed offsets; Color repeats the fractal at two more seed offsets (its red channel is
 * Fac). As in the node, the lookup is at Vector * Scale (and W * Scale in 4D).
 *
 * One texture function per (dimensions, output), since a graph node has one output:
 *
 *   float  blNoise1DFac  (float w, float scale, ... as below)        1D: uses w only
 *   float3 blNoise1DColor(float w, float scale, ...)
 *   float  blNoise2DFac  (float3 vector, float scale, float detail, float roughness,
 *                         float lacunarity, float offset, float gain, float distortion,
 *                         int type, int normalize)                    2D: uses vector.xy
 *   float3 blNoise2DColor(same parameters)
 *   float  blNoise3DFac  (same parameters)
 *   float3 blNoise3DColor(same parameters)
 *   float  blNoise4DFac  (float3 vector, float w, then the same parameters as above)
 *   float3 blNoise4DColor(float3 vector, float w, ...)
 *
 * Parameters (the node's sockets and properties; defaults are Blender's):
 *
 *   | name       | type   | default | meaning                                                |
 *   |------------|--------|---------|--------------------------------------------------------|
 *   | vector     | float3 | -       | lookup point; Blender's default is Generated coordinates |
 *   | w          | float  | 0.0     | fourth coordinate (4D), the coordinate (1D)            |
 *   | scale      | float  | 5.0     | lattice cells per unit of vector                       |
 *   | detail     | float  | 2.0     | octaves beyond the first, clamped to [0, 15]; fractional blends |
 *   | roughness  | float  | 0.5     | amplitude factor per octave (negative is taken as 0)   |
 *   | lacunarity | float  | 2.0     | frequency factor per octave                            |
 *   | offset     | float  | 0.0     | Hybrid/Ridged Multifractal and Hetero Terrain only     |
 *   | gain       | float  | 1.0     | Hybrid and Ridged Multifractal only                    |
 *   | distortion | float  | 0.0     | amount of domain warping                               |
 *   | type       | int    | 1       | 0 Multifractal, 1 fBM, 2 Hybrid Multifractal,          |
 *   |            |        |         | 3 Ridged Multifractal, 4 Hetero Terrain (Blender's enum) |
 *   | normalize  | int    | 1       | fBM only: 1 maps the sum to [0, 1], 0 leaves it about [-1, 1] |
 */

#include "hash.h"

/* Seed offsets in [100, 200] that decorrelate distortion and colour channels. */
float blSeedOffset(float seed, float channel) { return 100.0f + blHashFloat2(seed, channel) * 100.0f; }

float4 blSeedOffset4(float seed) {
  return (float4)(blSeedOffset(seed, 0.0f), blSeedOffset(seed, 1.0f), blSeedOffset(seed, 2.0f),
                  blSeedOffset(seed, 3.0f));
}

float blFade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float blNegateIf(float v, int cond) { return cond ? -v : v; }

/* floor(x) as an int, and the fraction x - floor(x) (Cycles' floorfrac). */
float blFloorFrac(float x, int *i) {
  float f = floor(x);
  *i = (int)f;
  return x - f;
}

float blGrad1(uint hash, float x) {
  int h = (int)(hash & 15U);
  float g = (float)(1 + (h & 7));
  return blNegateIf(g, h & 8) * x;
}

float blMix(float a, float b, float t) { return a + t * (b - a); }

float blPerlin1(float x) {
  int X;
  float fx = blFloorFrac(x, &X);
  return blMix(blGrad1(blHash1((uint)X), fx), blGrad1(blHash1((uint)(X + 1)), fx - 1.0f),
               blFade(fx));
}

/* The gradients of Cycles' Perlin noise, of four corners at once: corner l's hash h (lane l of
 * the hash) picks two (2D, 3D) or three (4D) of its offsets x, y, z, w and their signs.
 * select and BL_NEGATE_IF4 take the top bit of each mask lane, so each condition on h's low
 * bits is shifted there.
 * 2D: h & 4 ? y : x, plus twice h & 4 ? x : y; h & 1 negates the first, h & 2 the second. */
float4 blGrad2x4(uint4 h, float4 x, float4 y) {
  float4 u = select(x, y, h << 29U);
  float4 v = 2.0f * select(y, x, h << 29U);
  return BL_NEGATE_IF4(u, h << 31U) + BL_NEGATE_IF4(v, h << 30U);
}

/* The 4 corners of one 2D lattice cell in lanes (x, y) = (0, 0), (1, 0), (0, 1), (1, 1), blended
 * over x, then y, in the scalar order (blMix(blMix(c00, c10, u), blMix(c01, c11, u), v)). */
float blPerlin2(float x, float y) {
  float2 p = (float2)(x, y);
  float2 f = floor(p);
  int2 I = convert_int2(f);
  float2 fr = p - f;
  float2 uv = fr * fr * fr * (fr * (fr * 6.0f - 15.0f) + 10.0f);
  uint X0 = (uint)I.x, Y0 = (uint)I.y;
  uint4 h = blHash2x4((uint4)(X0, X0 + 1U, X0, X0 + 1U), (uint4)(Y0, Y0, Y0 + 1U, Y0 + 1U));
  float4 g = blGrad2x4(h, (float4)(fr.x, fr.x - 1.0f, fr.x, fr.x - 1.0f),
                       (float4)(fr.y, fr.y, fr.y - 1.0f, fr.y - 1.0f));
  float2 lo = (float2)(g.x, g.z), hi = (float2)(g.y, g.w);
  float2 ab = lo + uv.x * (hi - lo);
  return ab.x + uv.y * (ab.y - ab.x);
}

/* 3D: (h & 15) < 8 ? x : y (bit 3), plus (h & 15) < 4 ? y : (h & 15 is 12 or 14 ? x : z)
 * (bit 3 or 2; (h & 13) ^ 12 minus 1 wraps to all ones for 12 and 14 only); h & 1 negates the
 * first, h & 2 the second. */
float4 blGrad3x4(uint4 h, float4 x, float4 y, float4 z) {
  float4 u = select(x, y, h << 28U);
  float4 vt = select(z, x, ((h & 13U) ^ 12U) - 1U);
  float4 v = select(y, vt, (h | (h << 1U)) << 28U);
  return BL_NEGATE_IF4(u, h << 31U) + BL_NEGATE_IF4(v, h << 30U);
}

/* The 8 corner gradients of one 3D lattice cell, hashed and graded four at a time: lanes
 * (y, z) = (0, 0), (1, 0), (0, 1), (1, 1) of the cell at x = X and at X + 1; then blended over
 * x, y and z in the scalar order (blMix(blMix(c000, c100, u), blMix(c010, c110, u), v) for
 * z = Z, the same for Z + 1, then over z), so every value is the scalar code's, bit for bit. */
float blPerlin3(float x, float y, float z) {
  float4 p = (float4)(x, y, z, 0.0f);
  float4 f = floor(p);
  int4 I = convert_int4(f);
  float4 fr = p - f;
  float4 uvw = fr * fr * fr * (fr * (fr * 6.0f - 15.0f) + 10.0f);
  uint X0 = (uint)I.x;
  /* lanes by adding (0, 1, 0, 1) and (0, 0, 1, 1) to broadcasts (x - 0 is x): two vector
   * operations each where the element-wise literals cost extracts and inserts */
  uint4 Yl = (uint4)((uint)I.y) + (uint4)(0U, 1U, 0U, 1U);
  uint4 Zl = (uint4)((uint)I.z) + (uint4)(0U, 0U, 1U, 1U);
  float4 fy = (float4)(fr.y) - (float4)(0.0f, 1.0f, 0.0f, 1.0f);
  float4 fz = (float4)(fr.z) - (float4)(0.0f, 0.0f, 1.0f, 1.0f);
  float4 g0 = blGrad3x4(blHash3x4((uint4)(X0), Yl, Zl), (float4)(fr.x), fy, fz);
  float4 g1 = blGrad3x4(blHash3x4((uint4)(X0 + 1U), Yl, Zl), (float4)(fr.x - 1.0f), fy, fz);
  float4 m = g0 + uvw.x * (g1 - g0);
  float2 lo = (float2)(m.x, m.z), hi = (float2)(m.y, m.w);
  float2 ab = lo + uvw.y * (hi - lo);
  return ab.x + uvw.z * (ab.y - ab.x);
}

/* 4D: (h & 31) < 24 ? x : y (bits 4 and 3), plus (h & 31) < 16 ? y : z (bit 4), plus
 * (h & 31) < 8 ? z : w (bit 4 or 3); h & 1, 2, 4 negate them. */
float4 blGrad4x4(uint4 h, float4 x, float4 y, float4 z, float4 w) {
  float4 u = select(x, y, (h & (h << 1U)) << 27U);
  float4 v = select(y, z, h << 27U);
  float4 s = select(z, w, (h | (h << 1U)) << 27U);
  return BL_NEGATE_IF4(u, h << 31U) + BL_NEGATE_IF4(v, h << 30U) + BL_NEGATE_IF4(s, h << 29U);
}

/* One w-slice (W given, fw its fraction) of the 4D lattice cell: lanes and blends as in
 * blPerlin3. */
float blPerlin4Slice(uint X0, uint4 Yl, uint4 Zl, uint W, float4 fr, float4 fy, float4 fz,
                     float fw, float4 uvts) {
  float4 g0 = blGrad4x4(blHash4x4((uint4)(X0), Yl, Zl, (uint4)(W)), (float4)(fr.x), fy, fz,
                        (float4)(fw));
  float4 g1 = blGrad4x4(blHash4x4((uint4)(X0 + 1U), Yl, Zl, (uint4)(W)), (float4)(fr.x - 1.0f),
                        fy, fz, (float4)(fw));
  float4 m = g0 + uvts.x * (g1 - g0);
  float2 lo = (float2)(m.x, m.z), hi = (float2)(m.y, m.w);
  float2 ab = lo + uvts.y * (hi - lo);
  return ab.x + uvts.z * (ab.y - ab.x);
}

float blPerlin4(float x, float y, float z, float w) {
  float4 p = (float4)(x, y, z, w);
  float4 f = floor(p);
  int4 I = convert_int4(f);
  float4 fr = p - f;
  float4 uvts = fr * fr * fr * (fr * (fr * 6.0f - 15.0f) + 10.0f);
  uint Y0 = (uint)I.y, Z0 = (uint)I.z, W0 = (uint)I.w;
  uint4 Yl = (uint4)(Y0, Y0 + 1U, Y0, Y0 + 1U), Zl = (uint4)(Z0, Z0, Z0 + 1U, Z0 + 1U);
  float4 fy = (float4)(fr.y, fr.y - 1.0f, fr.y, fr.y - 1.0f);
  float4 fz = (float4)(fr.z, fr.z, fr.z - 1.0f, fr.z - 1.0f);
  float a = blPerlin4Slice((uint)I.x, Yl, Zl, W0, fr, fy, fz, fr.w, uvts);
  float b = blPerlin4Slice((uint)I.x, Yl, Zl, W0 + 1U, fr, fy, fz, fr.w - 1.0f, uvts);
  return a + uvts.w * (b - a);
}

/* Signed noise of dimension dims (1..4; 1D uses p.w) at p: wrapped every 100000 as Blender
 * does, then scaled by the factors that make each dimension's range about [-1, 1]. */
float blWrap100k(float x) { return fabs(x) < 100000.0f ? x : fmod(x, 100000.0f); }

/* blSnoise at a point whose every component is under 100000 in magnitude (no wrap needed). */
float blSnoiseUnwrapped(float4 p, int dims) {
  if (dims == 1)
    return 0.25f * blPerlin1(p.w);
  if (dims == 2)
    return 0.6616f * blPerlin2(p.x, p.y);
  if (dims == 3)
    return 0.9820f * blPerlin3(p.x, p.y, p.z);
  return 0.8344f * blPerlin4(p.x, p.y, p.z, p.w);
}

float blSnoise(float4 p, int dims) {
  /* fmod(x, 100000) is x itself below 100000: skipping the call there changes no value. */
  return blSnoiseUnwrapped((float4)(blWrap100k(p.x), blWrap100k(p.y), blWrap100k(p.z),
                                    blWrap100k(p.w)), dims);
}

/* Whether blSnoise's wrap can change nothing in a fractal, so that its octaves may skip it (the
 * tests, and the fmod calls on their cold path, around which the octave's values were kept in
 * memory). a holds the magnitudes of the first octave's components, b those of the last's; the
 * octaves between are products of the first by |frequencies| between 1 and the last's (each
 * fractal multiplies by the same lacunarity every octave, so the magnitudes grow or shrink
 * monotonically, and float products round monotonically): no component of any octave reaches
 * 100000 when none of a and b does. A NaN or an infinity fails the test. */
int blUnder100k(float4 a, float4 b) {
  return a.x < 100000.0f && a.y < 100000.0f && a.z < 100000.0f && a.w < 100000.0f &&
         b.x < 100000.0f && b.y < 100000.0f && b.z < 100000.0f && b.w < 100000.0f;
}

/* The frequency of the octave after octave (int)detail of an fBM (fscale *= lacunarity from 1):
 * its fractional octave's, the largest or smallest of all. */
float blFbmLastFrequency(float detail, float lacunarity) {
  float fscale = 1.0f;
  for (int i = 0; i <= (int)detail; i++)
    fscale *= lacunarity;
  return fabs(fscale);
}

/* fBM's octaves are blSnoise(fscale * p): |fscale * c| rounds to |fscale| * |c|. */
int blFbmNoWrap(float4 p, float lastFrequency) {
  return blUnder100k(fabs(p), fabs(p) * lastFrequency);
}

/* blNoiseFbm with blSnoise's wrap (wrap = 1) or without it (0, where blFbmNoWrap holds). */
float blNoiseFbmOctaves(float4 p, int dims, float detail, float roughness, float lacunarity,
                        int normalize, int wrap) {
  float fscale = 1.0f, amp = 1.0f, maxamp = 0.0f, sum = 0.0f;
  for (int i = 0; i <= (int)detail; i++) {
    float t = wrap ? blSnoise(fscale * p, dims) : blSnoiseUnwrapped(fscale * p, dims);
    sum += t * amp;
    maxamp += amp;
    amp *= roughness;
    fscale *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f) {
    float t = wrap ? blSnoise(fscale * p, dims) : blSnoiseUnwrapped(fscale * p, dims);
    float sum2 = sum + t * amp;
    return normalize ? blMix(0.5f * sum / maxamp + 0.5f, 0.5f * sum2 / (maxamp + amp) + 0.5f, rmd)
                     : blMix(sum, sum2, rmd);
  }
  return normalize ? 0.5f * sum / maxamp + 0.5f : sum;
}

float blNoiseFbm(float4 p, int dims, float detail, float roughness, float lacunarity,
                 int normalize) {
  if (blFbmNoWrap(p, blFbmLastFrequency(detail, lacunarity)))
    return blNoiseFbmOctaves(p, dims, detail, roughness, lacunarity, normalize, 0);
  return blNoiseFbmOctaves(p, dims, detail, roughness, lacunarity, normalize, 1);
}

float blNoiseMultiFractal(float4 p, int dims, float detail, float roughness, float lacunarity) {
  float value = 1.0f, pwr = 1.0f;
  for (int i = 0; i <= (int)detail; i++) {
    value *= (pwr * blSnoise(p, dims) + 1.0f);
    pwr *= roughness;
    p *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f)
    value *= (rmd * pwr * blSnoise(p, dims) + 1.0f);
  return value;
}

float blNoiseHeteroTerrain(float4 p, int dims, float detail, float roughness, float lacunarity,
                           float offset) {
  float pwr = roughness;
  float value = offset + blSnoise(p, dims);
  p *= lacunarity;
  for (int i = 1; i <= (int)detail; i++) {
    float increment = (blSnoise(p, dims) + offset) * pwr * value;
    value += increment;
    pwr *= roughness;
    p *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f) {
    float increment = (blSnoise(p, dims) + offset) * pwr * value;
    value += rmd * increment;
  }
  return value;
}

float blNoiseHybridMultiFractal(float4 p, int dims, float detail, float roughness,
                                float lacunarity, float offset, float gain) {
  float pwr = 1.0f, value = 0.0f, weight = 1.0f;
  for (int i = 0; weight > 0.001f && i <= (int)detail; i++) {
    if (weight > 1.0f)
      weight = 1.0f;
    float signal = (blSnoise(p, dims) + offset) * pwr;
    pwr *= roughness;
    value += weight * signal;
    weight *= gain * signal;
    p *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f && weight > 0.001f) {
    if (weight > 1.0f)
      weight = 1.0f;
    float signal = (blSnoise(p, dims) + offset) * pwr;
    value += rmd * weight * signal;
  }
  return value;
}

float blNoiseRidgedMultiFractal(float4 p, int dims, float detail, float roughness,
                                float lacunarity, float offset, float gain) {
  float pwr = roughness;
  float signal = offset - fabs(blSnoise(p, dims));
  signal *= signal;
  float value = signal;
  for (int i = 1; i <= (int)detail; i++) {
    p *= lacunarity;
    float weight = clamp(signal * gain, 0.0f, 1.0f);
    signal = offset - fabs(blSnoise(p, dims));
    signal *= signal;
    signal *= weight;
    value += signal * pwr;
    pwr *= roughness;
  }
  return value;
}

float blNoiseSelect(float4 p, int dims, float detail, float roughness, float lacunarity,
                    float offset, float gain, int type, int normalize) {
  if (type == 0)
    return blNoiseMultiFractal(p, dims, detail, roughness, lacunarity);
  if (type == 2)
    return blNoiseHybridMultiFractal(p, dims, detail, roughness, lacunarity, offset, gain);
  if (type == 3)
    return blNoiseRidgedMultiFractal(p, dims, detail, roughness, lacunarity, offset, gain);
  if (type == 4)
    return blNoiseHeteroTerrain(p, dims, detail, roughness, lacunarity, offset);
  return blNoiseFbm(p, dims, detail, roughness, lacunarity, normalize);
}

/* Keeps the components a dimension uses (1D: w; 2D: x, y; 3D: x, y, z; 4D: all), zero
 * elsewhere, so that seed offsets added to unused components change nothing. */
float4 blNoiseMask(float4 p, int dims) {
  if (dims == 1)
    return (float4)(0.0f, 0.0f, 0.0f, p.w);
  if (dims == 2)
    return (float4)(p.x, p.y, 0.0f, 0.0f);
  if (dims == 3)
    return (float4)(p.x, p.y, p.z, 0.0f);
  return p;
}

/* The node's evaluation: channel 0 is Fac, 1 and 2 Color's green and blue. Blender numbers the
 * seed offsets of distortion first (one per dimension: seeds 0..dims-1), then those of the two
 * colour channels (seeds dims and dims + 1). */
float blNoiseTexture(float4 co, int dims, float scale, float detail, float roughness,
                     float lacunarity, float offset, float gain, float distortion, int type,
                     int normalize, int channel) {
  detail = clamp(detail, 0.0f, 15.0f);
  roughness = fmax(roughness, 0.0f);
  float4 p = blNoiseMask(co * scale, dims);
  if (dims == 1) {
    /* 1D seeds hash one word: 100 + hash(seed) * 100 (Cycles' random_float_offset). */
    if (distortion != 0.0f)
      p.w += blSnoise(p + (float4)(0.0f, 0.0f, 0.0f, 100.0f + blHashFloat1(0.0f) * 100.0f), 1) *
             distortion;
    if (channel > 0)
      p.w += 100.0f + blHashFloat1((float)channel) * 100.0f;
    return blNoiseSelect(p, 1, detail, roughness, lacunarity, offset, gain, type, normalize);
  }
  if (distortion != 0.0f) {
    float4 d = (float4)(0.0f, 0.0f, 0.0f, 0.0f);
    d.x = blSnoise(p + blNoiseMask(blSeedOffset4(0.0f), dims), dims);
    d.y = blSnoise(p + blNoiseMask(blSeedOffset4(1.0f), dims), dims);
    if (dims >= 3)
      d.z = blSnoise(p + blNoiseMask(blSeedOffset4(2.0f), dims), dims);
    if (dims == 4)
      d.w = blSnoise(p + blNoiseMask(blSeedOffset4(3.0f), dims), dims);
    p += d * distortion;
  }
  if (channel > 0)
    p += blNoiseMask(blSeedOffset4((float)(dims + channel - 1)), dims);
  return blNoiseSelect(p, dims, detail, roughness, lacunarity, offset, gain, type, normalize);
}

/* The fractals of three points at once (Color's three channels, dims 2..4): each channel's
 * arithmetic is that of blNoiseFbm, blNoiseMultiFractal, blNoiseHeteroTerrain or
 * blNoiseRidgedMultiFractal above, in the same order, so its values are theirs bit for bit; the
 * octaves of the three are interleaved, which keeps more independent work in flight (Noise 3D
 * Color Detail 7: 0.91x the time of three fractals one after the other). Hybrid Multifractal,
 * whose octave loop stops per channel, keeps blNoiseColor's three calls. */
float3 blSnoise3(float4 p0, float4 p1, float4 p2, float s, int dims) {
  return (float3)(blSnoise(s * p0, dims), blSnoise(s * p1, dims), blSnoise(s * p2, dims));
}

/* blSnoise3 without the wrap (wrap = 0: where blUnder100k holds for the fractal). */
float3 blSnoise3W(float4 p0, float4 p1, float4 p2, float s, int dims, int wrap) {
  if (wrap)
    return blSnoise3(p0, p1, p2, s, dims);
  return (float3)(blSnoiseUnwrapped(s * p0, dims), blSnoiseUnwrapped(s * p1, dims),
                  blSnoiseUnwrapped(s * p2, dims));
}

float3 blNoiseFbm3Octaves(float4 p0, float4 p1, float4 p2, int dims, float detail,
                          float roughness, float lacunarity, int normalize, int wrap) {
  float fscale = 1.0f, amp = 1.0f, maxamp = 0.0f;
  float3 sum = (float3)(0.0f);
  for (int i = 0; i <= (int)detail; i++) {
    sum += blSnoise3W(p0, p1, p2, fscale, dims, wrap) * amp;
    maxamp += amp;
    amp *= roughness;
    fscale *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f) {
    float3 sum2 = sum + blSnoise3W(p0, p1, p2, fscale, dims, wrap) * amp;
    if (normalize) {
      float3 a = 0.5f * sum / maxamp + 0.5f, b = 0.5f * sum2 / (maxamp + amp) + 0.5f;
      return a + rmd * (b - a);
    }
    return sum + rmd * (sum2 - sum);
  }
  return normalize ? 0.5f * sum / maxamp + 0.5f : sum;
}

float3 blNoiseFbm3(float4 p0, float4 p1, float4 p2, int dims, float detail, float roughness,
                   float lacunarity, int normalize) {
  float f = blFbmLastFrequency(detail, lacunarity);
  if (blFbmNoWrap(p0, f) && blFbmNoWrap(p1, f) && blFbmNoWrap(p2, f))
    return blNoiseFbm3Octaves(p0, p1, p2, dims, detail, roughness, lacunarity, normalize, 0);
  return blNoiseFbm3Octaves(p0, p1, p2, dims, detail, roughness, lacunarity, normalize, 1);
}

float3 blNoiseMultiFractal3(float4 p0, float4 p1, float4 p2, int dims, float detail,
                            float roughness, float lacunarity) {
  float3 value = (float3)(1.0f);
  float pwr = 1.0f;
  for (int i = 0; i <= (int)detail; i++) {
    value *= (pwr * blSnoise3(p0, p1, p2, 1.0f, dims) + 1.0f);
    pwr *= roughness;
    p0 *= lacunarity;
    p1 *= lacunarity;
    p2 *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f)
    value *= (rmd * pwr * blSnoise3(p0, p1, p2, 1.0f, dims) + 1.0f);
  return value;
}

float3 blNoiseHeteroTerrain3(float4 p0, float4 p1, float4 p2, int dims, float detail,
                             float roughness, float lacunarity, float offset) {
  float pwr = roughness;
  float3 value = offset + blSnoise3(p0, p1, p2, 1.0f, dims);
  p0 *= lacunarity;
  p1 *= lacunarity;
  p2 *= lacunarity;
  for (int i = 1; i <= (int)detail; i++) {
    value += (blSnoise3(p0, p1, p2, 1.0f, dims) + offset) * pwr * value;
    pwr *= roughness;
    p0 *= lacunarity;
    p1 *= lacunarity;
    p2 *= lacunarity;
  }
  float rmd = detail - floor(detail);
  if (rmd != 0.0f)
    value += rmd * ((blSnoise3(p0, p1, p2, 1.0f, dims) + offset) * pwr * value);
  return value;
}

float3 blNoiseRidgedMultiFractal3Octaves(float4 p0, float4 p1, float4 p2, int dims,
                                         float detail, float roughness, float lacunarity,
                                         float offset, float gain, int wrap) {
  float pwr = roughness;
  float3 signal = offset - fabs(blSnoise3W(p0, p1, p2, 1.0f, dims, wrap));
  signal *= signal;
  float3 value = signal;
  for (int i = 1; i <= (int)detail; i++) {
    p0 *= lacunarity;
    p1 *= lacunarity;
    p2 *= lacunarity;
    /* the scalar clamp per channel, as blNoiseRidgedMultiFractal */
    float3 weight = (float3)(clamp(signal.x * gain, 0.0f, 1.0f),
                             clamp(signal.y * gain, 0.0f, 1.0f),
                             clamp(signal.z * gain, 0.0f, 1.0f));
    signal = offset - fabs(blSnoise3W(p0, p1, p2, 1.0f, dims, wrap));
    signal *= signal;
    signal *= weight;
    value += signal * pwr;
    pwr *= roughness;
  }
  return value;
}

/* Ridged's octaves are blSnoise(p) with p *= lacunarity after each: |p * lacunarity| rounds to
 * |p| * |lacunarity|, so the last octave's magnitudes are computed exactly here. */
float3 blNoiseRidgedMultiFractal3(float4 p0, float4 p1, float4 p2, int dims, float detail,
                                  float roughness, float lacunarity, float offset, float gain) {
  float4 a0 = fabs(p0), a1 = fabs(p1), a2 = fabs(p2);
  float l = fabs(lacunarity);
  for (int i = 1; i <= (int)detail; i++) {
    a0 *= l;
    a1 *= l;
    a2 *= l;
  }
  if (blUnder100k(fabs(p0), a0) && blUnder100k(fabs(p1), a1) && blUnder100k(fabs(p2), a2))
    return blNoiseRidgedMultiFractal3Octaves(p0, p1, p2, dims, detail, roughness, lacunarity,
                                             offset, gain, 0);
  return blNoiseRidgedMultiFractal3Octaves(p0, p1, p2, dims, detail, roughness, lacunarity,
                                           offset, gain, 1);
}

float3 blNoiseColor(float4 co, int dims, float scale, float detail, float roughness,
                    float lacunarity, float offset, float gain, float distortion, int type,
                    int normalize) {
  if (dims >= 2 && type != 2) {
    /* blNoiseTexture's points of the three channels, then their fractals together. */
    float dt = clamp(detail, 0.0f, 15.0f), r = fmax(roughness, 0.0f);
    float4 p = blNoiseMask(co * scale, dims);
    if (distortion != 0.0f) {
      float4 d = (float4)(0.0f, 0.0f, 0.0f, 0.0f);
      d.x = blSnoise(p + blNoiseMask(blSeedOffset4(0.0f), dims), dims);
      d.y = blSnoise(p + blNoiseMask(blSeedOffset4(1.0f), dims), dims);
      if (dims >= 3)
        d.z = blSnoise(p + blNoiseMask(blSeedOffset4(2.0f), dims), dims);
      if (dims == 4)
        d.w = blSnoise(p + blNoiseMask(blSeedOffset4(3.0f), dims), dims);
      p += d * distortion;
    }
    float4 p1 = p + blNoiseMask(blSeedOffset4((float)dims), dims);
    float4 p2 = p + blNoiseMask(blSeedOffset4((float)(dims + 1)), dims);
    if (type == 0)
      return blNoiseMultiFractal3(p, p1, p2, dims, dt, r, lacunarity);
    if (type == 3)
      return blNoiseRidgedMultiFractal3(p, p1, p2, dims, dt, r, lacunarity, offset, gain);
    if (type == 4)
      return blNoiseHeteroTerrain3(p, p1, p2, dims, dt, r, lacunarity, offset);
    return blNoiseFbm3(p, p1, p2, dims, dt, r, lacunarity, normalize);
  }
  float3 c;
  c.x = blNoiseTexture(co, dims, scale, detail, roughness, lacunarity, offset, gain, distortion,
                       type, normalize, 0);
  c.y = blNoiseTexture(co, dims, scale, detail, roughness, lacunarity, offset, gain, distortion,
                       type, normalize, 1);
  c.z = blNoiseTexture(co, dims, scale, detail, roughness, lacunarity, offset, gain, distortion,
                       type, normalize, 2);
  return c;
}

float blNoise1DFac(float w, float scale, float detail, float roughness, float lacunarity,
                   float offset, float gain, float distortion, int type, int normalize) {
  return blNoiseTexture((float4)(0.0f, 0.0f, 0.0f, w), 1, scale, detail, roughness, lacunarity,
                        offset, gain, distortion, type, normalize, 0);
}

float3 blNoise1DColor(float w, float scale, float detail, float roughness, float lacunarity,
                      float offset, float gain, float distortion, int type, int normalize) {
  return blNoiseColor((float4)(0.0f, 0.0f, 0.0f, w), 1, scale, detail, roughness, lacunarity,
                      offset, gain, distortion, type, normalize);
}

float blNoise2DFac(float3 vector, float scale, float detail, float roughness,
                   float lacunarity, float offset, float gain, float distortion, int type,
                   int normalize) {
  return blNoiseTexture((float4)(vector, 0.0f), 2, scale, detail, roughness, lacunarity, offset, gain,
                        distortion, type, normalize, 0);
}

float3 blNoise2DColor(float3 vector, float scale, float detail, float roughness,
                      float lacunarity, float offset, float gain, float distortion, int type,
                      int normalize) {
  return blNoiseColor((float4)(vector, 0.0f), 2, scale, detail, roughness, lacunarity, offset, gain,
                      distortion, type, normalize);
}

float blNoise3DFac(float3 vector, float scale, float detail, float roughness,
                   float lacunarity, float offset, float gain, float distortion, int type,
                   int normalize) {
  return blNoiseTexture((float4)(vector, 0.0f), 3, scale, detail, roughness, lacunarity, offset, gain,
                        distortion, type, normalize, 0);
}

float3 blNoise3DColor(float3 vector, float scale, float detail, float roughness,
                      float lacunarity, float offset, float gain, float distortion, int type,
                      int normalize) {
  return blNoiseColor((float4)(vector, 0.0f), 3, scale, detail, roughness, lacunarity, offset, gain,
                      distortion, type, normalize);
}

float blNoise4DFac(float3 vector, float w, float scale, float detail, float roughness,
                   float lacunarity, float offset, float gain, float distortion, int type,
                   int normalize) {
  return blNoiseTexture((float4)(vector, w), 4, scale, detail, roughness, lacunarity, offset, gain,
                        distortion, type, normalize, 0);
}

float3 blNoise4DColor(float3 vector, float w, float scale, float detail, float roughness,
                      float lacunarity, float offset, float gain, float distortion, int type,
                      int normalize) {
  return blNoiseColor((float4)(vector, w), 4, scale, detail, roughness, lacunarity, offset, gain,
                      distortion, type, normalize);
}

/* Wave Texture (Blender's node, built on the 3D fBM above): bands or rings of a sine, saw or
 * triangle profile, distorted by fBM noise.
 *
 *   float  blWaveFac(float3 vector, float scale, float distortion, float detail,
 *                    float detailScale, float detailRoughness, float phaseOffset, int waveType,
 *                    int direction, int profile)
 *   float3 blWaveColor(same parameters)                      (Fac, Fac, Fac)
 *
 *   | name            | type   | default | meaning                                        |
 *   |-----------------|--------|---------|------------------------------------------------|
 *   | scale           | float  | 5.0     | waves per unit of vector (x 20 / 2 pi)         |
 *   | distortion      | float  | 0.0     | amount of fBM added to the phase               |
 *   | detail          | float  | 2.0     | fBM octaves beyond the first                   |
 *   | detailScale     | float  | 1.0     | fBM frequency                                  |
 *   | detailRoughness | float  | 0.5     | fBM roughness                                  |
 *   | phaseOffset     | float  | 0.0     | added to the phase                             |
 *   | waveType        | int    | 0       | 0 Bands, 1 Rings                               |
 *   | direction       | int    | 0       | Bands: 0 X, 1 Y, 2 Z, 3 Diagonal; Rings: 0 X, 1 Y, 2 Z, 3 Spherical |
 *   | profile         | int    | 0       | 0 Sine, 1 Saw, 2 Triangle                      |
 */
/* Cycles' sine profile, 0.5 + 0.5 sin(n - pi/2), with n - pi/2 rounded to float as Cycles rounds
 * it (past n = 3000 its half ulp moves the value by more than 1e-4). sin(m) by a reduction by pi
 * in two parts (float(pi) and the rest) to r in [-pi/2, pi/2], where the Taylor series to the
 * 11th power is within 6e-8 of sin, and the sign of k's parity. Past 2^21 pi the float quotient
 * m / pi no longer rounds to within one of its integer (r would leave the series' range): there
 * OpenCL's sin, which reduces any float, and which spent 14-36 ns a sample on PoCL where it ran
 * for every point (Wave, Detail 7: 201 -> 166 ns without it; bench/texture-speed.md). */
float blWaveSine(float n) {
  float m = n - 1.57079632679489661923f;
  if (!(fabs(m) < 6588397.5f))
    return 0.5f + 0.5f * sin(m);
  float k = floor(m * 0.318309886183790672f + 0.5f);
  float r = fma(-k, 3.14159274101257324f, m);
  r = fma(-k, -8.74227766e-08f, r);
  float r2 = r * r;
  float s = r * (1.0f + r2 * (-1.66666667e-01f + r2 * (8.33333333e-03f + r2 * (-1.98412698e-04f +
                r2 * (2.75573192e-06f + r2 * -2.50521084e-08f)))));
  return 0.5f + 0.5f * (((int)k & 1) ? -s : s);
}

float blWaveFac(float3 vector, float scale, float distortion, float detail, float detailScale,
                float detailRoughness, float phaseOffset, int waveType, int direction,
                int profile) {
  float3 p = (vector * scale + 0.000001f) * 0.999999f;
  float n;
  if (waveType == 0) {
    if (direction == 0)
      n = p.x * 20.0f;
    else if (direction == 1)
      n = p.y * 20.0f;
    else if (direction == 2)
      n = p.z * 20.0f;
    else
      n = (p.x + p.y + p.z) * 10.0f;
  } else {
    float3 rp = p;
    if (direction == 0)
      rp.x = 0.0f;
    else if (direction == 1)
      rp.y = 0.0f;
    else if (direction == 2)
      rp.z = 0.0f;
    n = sqrt(rp.x * rp.x + rp.y * rp.y + rp.z * rp.z) * 20.0f;
  }
  n += phaseOffset;
  if (distortion != 0.0f)
    n += distortion * (blNoiseFbm((float4)(p * detailScale, 0.0f), 3, detail, detailRoughness,
                                  2.0f, 1) * 2.0f - 1.0f);
  if (profile == 0)
    return blWaveSine(n);
  n /= 6.28318530717958647692f;
  if (profile == 1)
    return n - floor(n);
  return fabs(n - floor(n + 0.5f)) * 2.0f;
}

float3 blWaveColor(float3 vector, float scale, float distortion, float detail, float detailScale,
                   float detailRoughness, float phaseOffset, int waveType, int direction,
                   int profile) {
  return (float3)(blWaveFac(vector, scale, distortion, detail, detailScale, detailRoughness,
                            phaseOffset, waveType, direction, profile));
}
