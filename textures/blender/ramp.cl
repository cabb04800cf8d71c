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
 */

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
