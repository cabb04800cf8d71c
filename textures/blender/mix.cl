/* blender/mix.cl: Blender's Mix node (Cycles, Blender 5.0): Float, Vector (uniform and
 * non-uniform factor) and Color with every blend mode, value for value.
 *
 *   float  blMixFloat(float factor, float a, float b, int clampFactor)
 *   float3 blMixVector(float factor, float3 a, float3 b, int clampFactor)
 *   float3 blMixVectorNonUniform(float3 factor, float3 a, float3 b, int clampFactor)
 *   float3 blMixColor(float factor, float3 a, float3 b, int blendType, int clampFactor,
 *                     int clampResult)
 *
 * Parameters (Blender's defaults):
 *
 *   | name        | type         | default | meaning                                          |
 *   |-------------|--------------|---------|--------------------------------------------------|
 *   | factor      | float/float3 | 0.5     | 0 gives a, 1 gives b (per component if float3)   |
 *   | a, b        | float/float3 | 0 (color 0.5) | the inputs                                 |
 *   | blendType   | int          | 0       | 0 Mix, 1 Darken, 2 Multiply, 3 Color Burn, 4 Lighten, 5 Screen, |
 *   |             |              |         | 6 Color Dodge, 7 Add, 8 Overlay, 9 Soft Light, 10 Linear Light, |
 *   |             |              |         | 11 Difference, 12 Exclusion, 13 Subtract, 14 Divide, 15 Hue, |
 *   |             |              |         | 16 Saturation, 17 Color, 18 Value (the menu's order) |
 *   | clampFactor | int          | 1       | 1 clamps factor to [0, 1]                        |
 *   | clampResult | int          | 0       | Color only: 1 clamps the result to [0, 1]        |
 */

#include "color.h"

float blMixSaturate(float x) { return fmin(fmax(x, 0.0f), 1.0f); }

float3 blInterp(float3 a, float3 b, float t) { return (1.0f - t) * a + t * b; }

float blMixOverlay(float t, float a, float b) {
  float tm = 1.0f - t;
  return a < 0.5f ? a * (tm + 2.0f * t * b) : 1.0f - (tm + 2.0f * t * (1.0f - b)) * (1.0f - a);
}

float blMixDivide(float t, float a, float b) {
  return b != 0.0f ? (1.0f - t) * a + t * a / b : a;
}

float blMixDodge(float t, float a, float b) {
  if (a == 0.0f)
    return a;
  float tmp = 1.0f - t * b;
  if (tmp <= 0.0f)
    return 1.0f;
  tmp = a / tmp;
  return tmp > 1.0f ? 1.0f : tmp;
}

float blMixBurn(float t, float a, float b) {
  float tmp = (1.0f - t) + t * b;
  if (tmp <= 0.0f)
    return 0.0f;
  tmp = 1.0f - (1.0f - a) / tmp;
  return tmp < 0.0f ? 0.0f : (tmp > 1.0f ? 1.0f : tmp);
}

/* Cycles' svm_mix for one blend mode (numbered as in Blender's menu, see above). */
float3 blBlend(int mode, float t, float3 a, float3 b) {
  float tm = 1.0f - t;
  float3 one = (float3)(1.0f);
  switch (mode) {
  case 1: return blInterp(a, fmin(a, b), t);
  case 2: return blInterp(a, a * b, t);
  case 3: return (float3)(blMixBurn(t, a.x, b.x), blMixBurn(t, a.y, b.y), blMixBurn(t, a.z, b.z));
  case 4: return blInterp(a, fmax(a, b), t);
  case 5: return one - ((float3)(tm) + t * (one - b)) * (one - a);
  case 6: return (float3)(blMixDodge(t, a.x, b.x), blMixDodge(t, a.y, b.y), blMixDodge(t, a.z, b.z));
  case 7: return blInterp(a, a + b, t);
  case 8:
    return (float3)(blMixOverlay(t, a.x, b.x), blMixOverlay(t, a.y, b.y),
                    blMixOverlay(t, a.z, b.z));
  case 9: {
    float3 scr = one - (one - b) * (one - a);
    return tm * a + t * ((one - a) * b * a + a * scr);
  }
  case 10: return a + t * (2.0f * b + (float3)(-1.0f));
  case 11: return blInterp(a, fabs(a - b), t);
  case 12: return fmax(blInterp(a, a + b - 2.0f * a * b, t), (float3)(0.0f));
  case 13: return blInterp(a, a - b, t);
  case 14:
    return (float3)(blMixDivide(t, a.x, b.x), blMixDivide(t, a.y, b.y), blMixDivide(t, a.z, b.z));
  case 15: {
    float3 hsv2 = blRgbToHsv(b);
    if (hsv2.y == 0.0f)
      return a;
    float3 hsv = blRgbToHsv(a);
    hsv.x = hsv2.x;
    return blInterp(a, blHsvToRgb(hsv), t);
  }
  case 16: {
    float3 hsv = blRgbToHsv(a);
    if (hsv.y == 0.0f)
      return a;
    hsv.y = tm * hsv.y + t * blRgbToHsv(b).y;
    return blHsvToRgb(hsv);
  }
  case 17: {
    float3 hsv2 = blRgbToHsv(b);
    if (hsv2.y == 0.0f)
      return a;
    float3 hsv = blRgbToHsv(a);
    hsv.x = hsv2.x;
    hsv.y = hsv2.y;
    return blInterp(a, blHsvToRgb(hsv), t);
  }
  case 18: {
    float3 hsv = blRgbToHsv(a);
    hsv.z = tm * hsv.z + t * blRgbToHsv(b).z;
    return blHsvToRgb(hsv);
  }
  default: return blInterp(a, b, t);
  }
}

float blMixFloat(float factor, float a, float b, int clampFactor) {
  float t = clampFactor ? blMixSaturate(factor) : factor;
  return a * (1.0f - t) + b * t;
}

float3 blMixVector(float factor, float3 a, float3 b, int clampFactor) {
  float t = clampFactor ? blMixSaturate(factor) : factor;
  return a * (1.0f - t) + b * t;
}

float3 blMixVectorNonUniform(float3 factor, float3 a, float3 b, int clampFactor) {
  float3 t = clampFactor ? clamp(factor, 0.0f, 1.0f) : factor;
  return a * ((float3)(1.0f) - t) + b * t;
}

float3 blMixColor(float factor, float3 a, float3 b, int blendType, int clampFactor,
                  int clampResult) {
  float t = clampFactor ? blMixSaturate(factor) : factor;
  float3 r = blBlend(blendType, t, a, b);
  return clampResult ? clamp(r, 0.0f, 1.0f) : r;
}
