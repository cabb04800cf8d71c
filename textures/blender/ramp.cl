/* blender/ramp.cl: Blender's Color Ramp node (Cycles, Blender 5.0), value for value.
 *
 * Blender evaluates the colour band at 257 evenly spaced positions i / 256 (Linear, Ease,
 * B-Spline, Cardinal or Constant between the stops) and Cycles looks Fac up in that table:
 * linearly between two entries, except in Constant mode, which takes the entry at or below.
 * This file does the same, computing the two table entries it needs, so a ramp's values (and
 * its Constant steps, which fall on table positions, not on the stops) are Blender's.
 *
 *   float3 blColorRampColor(float fac, __global const float4 *colors,
 *                           __global const float *positions, int count, int interpolation)
 *   float  blColorRampAlpha(same parameters)
 *   float3 blColorRampHueColor(float fac, __global const float4 *colors,
 *                              __global const float *positions, int count, int interpolation,
 *                              int colorMode, int hueInterpolation)
 *   float  blColorRampHueAlpha(same parameters)
 *                                the ramp in HSV or HSL colour mode: the band mixes the stops'
 *                                hue (the way hueInterpolation says), saturation and value or
 *                                lightness, always linearly between stops (Blender ignores
 *                                Ease, B-Spline and Cardinal there); interpolation only says
 *                                whether the table lookup interpolates (not when Constant)
 *
 * Parameters (Blender's defaults):
 *
 *   | name          | type                 | default          | meaning                       |
 *   |---------------|----------------------|------------------|-------------------------------|
 *   | fac           | float                | 0.5              | lookup position               |
 *   | colors        | __global const float4* | black, white   | RGBA of each stop, in position order |
 *   | positions     | __global const float*  | 0.0, 1.0       | the stops' positions, ascending |
 *   | count         | int                  | 2                | number of stops (>= 1)        |
 *   | interpolation | int                  | 0                | 0 Linear, 1 Ease, 2 B-Spline, 3 Cardinal, 4 Constant |
 *   | colorMode     | int                  | 1                | 1 HSV, 2 HSL (0 RGB: blColorRampColor) |
 *   | hueInterpolation | int               | 0                | 0 Near, 1 Far, 2 Clockwise, 3 Counter-Clockwise |
 */

#include "color.h"

/* Blender's key_curve_position_weights for Cardinal (tension 0.71) and B-Spline. */
float4 blRampWeights(float t, int interpolation) {
  float t2 = t * t, t3 = t2 * t;
  if (interpolation == 3) {
    float fc = 0.71f;
    return (float4)(-fc * t3 + 2.0f * fc * t2 - fc * t, (2.0f - fc) * t3 + (fc - 3.0f) * t2 + 1.0f,
                    (fc - 2.0f) * t3 + (3.0f - 2.0f * fc) * t2 + fc * t, fc * t3 - fc * t2);
  }
  return (float4)(-0.16666666f * t3 + 0.5f * t2 - 0.5f * t + 0.16666666f,
                  0.5f * t3 - t2 + 0.66666666f, -0.5f * t3 + 0.5f * t2 + 0.5f * t + 0.16666666f,
                  0.16666666f * t3);
}

/* The colour band at position in (Blender's BKE_colorband_evaluate, RGB colour mode). */
float4 blColorBand(float in, __global const float4 *colors, __global const float *positions,
                   int count, int interpolation) {
  int smooth = interpolation == 2 || interpolation == 3;
  if (count <= 1 || (in <= positions[0] && !smooth))
    return colors[0];
  int a = 0;
  while (a < count && positions[a] <= in)
    a++;
  /* right (index r, position rpos) is the first stop past in; left (l, lpos) the one before.
   * Past the last stop, right is a copy of the last at 1; before the first, left a copy of the
   * first at 0. */
  int r = a == count ? count - 1 : a;
  int l = a == count ? count - 1 : (a == 0 ? 0 : a - 1);
  float rpos = a == count ? 1.0f : positions[r];
  float lpos = a == 0 ? 0.0f : positions[l];
  if (a == count && !smooth)
    return colors[l];
  if (interpolation == 4)
    return colors[l];
  float fac = lpos != rpos ? (in - rpos) / (lpos - rpos) : (a != count ? 0.0f : 1.0f);
  if (smooth) {
    int r2 = a >= count - 1 ? r : r + 1;
    int l2 = a < 2 ? l : l - 1;
    fac = clamp(fac, 0.0f, 1.0f);
    float4 w = blRampWeights(fac, interpolation);
    float4 out = w.w * colors[l2] + w.z * colors[l] + w.y * colors[r] + w.x * colors[r2];
    return clamp(out, 0.0f, 1.0f);
  }
  if (interpolation == 1) {
    float fac2 = fac * fac;
    fac = 3.0f * fac2 - 2.0f * fac2 * fac;
  }
  float mfac = 1.0f - fac;
  return mfac * colors[r] + fac * colors[l];
}

/* Cycles' rgb_ramp_lookup over the 257-entry table, computing only the entries it reads. */
float4 blColorRamp(float fac, __global const float4 *colors, __global const float *positions,
                   int count, int interpolation) {
  float f = clamp(fac, 0.0f, 1.0f) * 256.0f;
  int i = clamp((int)f, 0, 256);
  float t = f - (float)i;
  float4 a = blColorBand((float)i / 256.0f, colors, positions, count,
                         interpolation);
  if (interpolation != 4 && t > 0.0f) {
    float4 b = blColorBand((float)(i + 1) / 256.0f, colors, positions,
                           count, interpolation);
    a = (1.0f - t) * a + t * b;
  }
  return a;
}

float3 blColorRampColor(float fac, __global const float4 *colors, __global const float *positions,
                        int count, int interpolation) {
  return blColorRamp(fac, colors, positions, count, interpolation).xyz;
}

float blColorRampAlpha(float fac, __global const float4 *colors, __global const float *positions,
                       int count, int interpolation) {
  return blColorRamp(fac, colors, positions, count, interpolation).w;
}

/* Blender's own RGB <-> HSV of the colour band (BLI math_color, not Cycles' util/color.h that
 * color.h follows: the two round differently, and a hue of exactly 1 needs the band's rules). */
float3 blBandRgbToHsv(float4 c) {
  float r = c.x, g = c.y, b = c.z, k = 0.0f;
  if (g < b) {
    float t = g;
    g = b;
    b = t;
    k = -1.0f;
  }
  float lowest = b;
  if (r < g) {
    float t = r;
    r = g;
    g = t;
    k = -2.0f / 6.0f - k;
    lowest = fmin(g, b);
  }
  float chroma = r - lowest;
  return (float3)(fabs(k + (g - b) / (6.0f * chroma + 1e-20f)), chroma / (r + 1e-20f), r);
}

float3 blBandHsvToRgb(float3 hsv) {
  float3 n = (float3)(fabs(hsv.x * 6.0f - 3.0f) - 1.0f, 2.0f - fabs(hsv.x * 6.0f - 2.0f),
                      2.0f - fabs(hsv.x * 6.0f - 4.0f));
  n = clamp(n, 0.0f, 1.0f);
  return ((n - 1.0f) * hsv.y + 1.0f) * hsv.z;
}

/* One hue between a stop's (weight 1 - f) and the next's (weight f), the way Blender's
 * hue interpolation mode says: 0 the nearer way round, 1 the farther (a full turn between equal
 * hues), 2 clockwise, 3 counter-clockwise. Hues of 1 and more count from 0. */
float blBandHue(int mode, float f, float a, float b) {
  a = a < 1.0f ? a : a - 1.0f;
  b = b < 1.0f ? b : b - 1.0f;
  int turn = 0; /* 1: a goes round once more; 2: b does */
  if (mode == 0)
    turn = (a < b && b - a > 0.5f) ? 1 : ((a > b && b - a < -0.5f) ? 2 : 0);
  else if (mode == 1)
    turn = a == b ? 1 : ((a < b && b - a < 0.5f) ? 1 : ((a > b && b - a > -0.5f) ? 2 : 0));
  else if (mode == 3)
    turn = a > b ? 2 : 0;
  else
    turn = a < b ? 1 : 0;
  float h = (1.0f - f) * (a + (turn == 1 ? 1.0f : 0.0f)) + f * (b + (turn == 2 ? 1.0f : 0.0f));
  return turn != 0 && h >= 1.0f ? h - 1.0f : h;
}

/* The band at position in, mixed in HSV (colorMode 1) or HSL (2): before the first stop its
 * colour, past the last the last's, else linear between the stops around in. */
float4 blColorBandHue(float in, __global const float4 *colors, __global const float *positions,
                      int count, int colorMode, int hueInterpolation) {
  if (count <= 1 || in <= positions[0])
    return colors[0];
  int a = 0;
  while (a < count && positions[a] <= in)
    a++;
  if (a == count)
    return colors[count - 1];
  /* a > 0 here: in lies after stop a - 1 and before stop a. */
  float4 next = colors[a], prev = colors[a - 1];
  float npos = positions[a], ppos = positions[a - 1];
  float f = ppos != npos ? (in - npos) / (ppos - npos) : 0.0f; /* weight of prev */
  float3 hn = colorMode == 2 ? blRgbToHsl(next.xyz) : blBandRgbToHsv(next);
  float3 hp = colorMode == 2 ? blRgbToHsl(prev.xyz) : blBandRgbToHsv(prev);
  float3 h = (float3)(blBandHue(hueInterpolation, f, hn.x, hp.x), (1.0f - f) * hn.y + f * hp.y,
                      (1.0f - f) * hn.z + f * hp.z);
  float3 rgb = colorMode == 2 ? blHslToRgb(h) : blBandHsvToRgb(h);
  return (float4)(rgb, (1.0f - f) * next.w + f * prev.w);
}

float4 blColorRampHue(float fac, __global const float4 *colors, __global const float *positions,
                      int count, int interpolation, int colorMode, int hueInterpolation) {
  float x = clamp(fac, 0.0f, 1.0f) * 256.0f;
  int i = clamp((int)x, 0, 256);
  float t = x - (float)i;
  float4 a = blColorBandHue((float)i / 256.0f, colors, positions, count, colorMode,
                            hueInterpolation);
  if (interpolation != 4 && t > 0.0f) {
    float4 b = blColorBandHue((float)(i + 1) / 256.0f, colors, positions, count, colorMode,
                              hueInterpolation);
    a = (1.0f - t) * a + t * b;
  }
  return a;
}

float3 blColorRampHueColor(float fac, __global const float4 *colors,
                           __global const float *positions, int count, int interpolation,
                           int colorMode, int hueInterpolation) {
  return blColorRampHue(fac, colors, positions, count, interpolation, colorMode,
                        hueInterpolation).xyz;
}

float blColorRampHueAlpha(float fac, __global const float4 *colors,
                          __global const float *positions, int count, int interpolation,
                          int colorMode, int hueInterpolation) {
  return blColorRampHue(fac, colors, positions, count, interpolation, colorMode,
                        hueInterpolation).w;
}
