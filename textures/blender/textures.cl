/* blender/textures.cl: Blender's Gradient, Checker, Magic and White Noise textures (Cycles,
 * Blender 5.0), value for value. (Wave is in noise.cl: it is built on fBM noise.)
 *
 *   float  blGradientFac(float3 vector, int gradientType)          clamped to [0, 1]
 *   float3 blGradientColor(float3 vector, int gradientType)        (Fac, Fac, Fac)
 *   float  blCheckerFac(float3 vector, float scale)                1 on color1's squares
 *   float3 blCheckerColor(float3 vector, float3 color1, float3 color2, float scale)
 *   float3 blMagicColor(float3 vector, float scale, float distortion, int depth)
 *   float  blMagicFac(float3 vector, float scale, float distortion, int depth)   mean of Color
 *   float  blWhiteNoise3DValue(float3 vector)                      hash of the bits, in [0, 1]
 *   float3 blWhiteNoise3DColor(float3 vector)
 *
 * Parameters (Blender's defaults):
 *
 *   | name         | type   | default | meaning                                             |
 *   |--------------|--------|---------|-----------------------------------------------------|
 *   | vector       | float3 | -       | lookup point (Blender's default: Generated coordinates) |
 *   | gradientType | int    | 0       | 0 Linear, 1 Quadratic, 2 Easing, 3 Diagonal, 4 Radial, |
 *   |              |        |         | 5 Quadratic Sphere, 6 Spherical (Cycles' numbering)  |
 *   | scale        | float  | 5.0     | Checker: squares per unit; Magic: frequency          |
 *   | color1/2     | float3 | 0.8 / 0.2 gray | Checker's colours                             |
 *   | distortion   | float  | 1.0     | Magic's distortion                                   |
 *   | depth        | int    | 2       | Magic's iterations, 0..10                            |
 */

#include "hash.h"

float blGradientFac(float3 vector, int gradientType) {
  float x = vector.x, y = vector.y, z = vector.z, f;
  if (gradientType == 0) {
    f = x;
  } else if (gradientType == 1) {
    float r = fmax(x, 0.0f);
    f = r * r;
  } else if (gradientType == 2) {
    float r = fmin(fmax(x, 0.0f), 1.0f);
    float t = r * r;
    f = 3.0f * t - 2.0f * t * r;
  } else if (gradientType == 3) {
    f = (x + y) * 0.5f;
  } else if (gradientType == 4) {
    f = atan2(y, x) / 6.28318530717958647692f + 0.5f;
  } else {
    /* Biased so that a unit-length vector gives exactly 0. */
    float r = fmax(0.999999f - sqrt(x * x + y * y + z * z), 0.0f);
    f = gradientType == 5 ? r * r : r;
  }
  return fmin(fmax(f, 0.0f), 1.0f);
}

float3 blGradientColor(float3 vector, int gradientType) {
  return (float3)(blGradientFac(vector, gradientType));
}

float blCheckerFac(float3 vector, float scale) {
  float3 p = vector * scale;
  /* Blender nudges the point so that integer coordinates do not flicker. */
  p.x = (p.x + 0.000001f) * 0.999999f;
  p.y = (p.y + 0.000001f) * 0.999999f;
  p.z = (p.z + 0.000001f) * 0.999999f;
  int xi = abs((int)floor(p.x)), yi = abs((int)floor(p.y)), zi = abs((int)floor(p.z));
  return ((xi % 2 == yi % 2) == (zi % 2)) ? 1.0f : 0.0f;
}

float3 blCheckerColor(float3 vector, float3 color1, float3 color2, float scale) {
  return blCheckerFac(vector, scale) == 1.0f ? color1 : color2;
}

float3 blMagicColor(float3 vector, float scale, float distortion, int depth) {
  float px = fmod(vector.x, 6.28318530717958647692f);
  float py = fmod(vector.y, 6.28318530717958647692f);
  float pz = fmod(vector.z, 6.28318530717958647692f);
  float x = sin((px + py + pz) * 5.0f * scale);
  float y = cos((-px + py - pz) * 5.0f * scale);
  float z = -cos((-px - py + pz) * 5.0f * scale);
  if (depth > 0) {
    x *= distortion;
    y *= distortion;
    z *= distortion;
    y = -cos(x - y + z) * distortion;
    if (depth > 1)
      x = cos(x - y - z) * distortion;
    if (depth > 2)
      z = sin(-x - y - z) * distortion;
    if (depth > 3)
      x = -cos(-x + y - z) * distortion;
    if (depth > 4)
      y = -sin(-x + y + z) * distortion;
    if (depth > 5)
      y = -cos(-x + y + z) * distortion;
    if (depth > 6)
      x = cos(x + y + z) * distortion;
    if (depth > 7)
      z = sin(x + y - z) * distortion;
    if (depth > 8)
      x = -cos(-x - y + z) * distortion;
    if (depth > 9)
      y = -sin(x - y + z) * distortion;
  }
  if (distortion != 0.0f) {
    float d = distortion * 2.0f;
    x /= d;
    y /= d;
    z /= d;
  }
  return (float3)(0.5f - x, 0.5f - y, 0.5f - z);
}

float blMagicFac(float3 vector, float scale, float distortion, int depth) {
  float3 c = blMagicColor(vector, scale, distortion, depth);
  return (c.x + c.y + c.z) * (1.0f / 3.0f);
}

float blWhiteNoise3DValue(float3 vector) { return blHashFloat3(vector.x, vector.y, vector.z); }

float3 blWhiteNoise3DColor(float3 vector) {
  return (float3)(blHashFloat3(vector.x, vector.y, vector.z),
                  blHashFloat4(vector.x, vector.y, vector.z, 1.0f),
                  blHashFloat4(vector.x, vector.y, vector.z, 2.0f));
}
