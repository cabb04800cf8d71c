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
 *   blWhiteNoise1DValue, blWhiteNoise1DColor (float w),
 *   blWhiteNoise2DValue, blWhiteNoise2DColor (float3 vector; x, y),
 *   blWhiteNoise4DValue, blWhiteNoise4DColor (float3 vector, float w): the other dimensions
 *   float3 blBrickColor(float3 vector, float3 color1, float3 color2, float3 mortar, float scale,
 *                       float mortarSize, float mortarSmooth, float bias, float brickWidth,
 *                       float rowHeight, float offsetAmount, int offsetFrequency,
 *                       float squashAmount, int squashFrequency)
 *   float  blBrickFac(the same without color1, color2, mortar)       1 in the mortar
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
 *   | color1/2, mortar | float3 | 0.8, 0.2, 0 | Brick: colours mixed by each brick's tint; mortar |
 *   | mortarSize   | float  | 0.02    | Brick: mortar width                                  |
 *   | mortarSmooth | float  | 0.1     | Brick: blur of the mortar edge                       |
 *   | bias         | float  | 0.0     | Brick: tint bias towards color1 (< 0) or color2     |
 *   | brickWidth, rowHeight | float | 0.5, 0.25 | Brick: brick size                          |
 *   | offsetAmount, offsetFrequency | float, int | 0.5, 2 | Brick: shift of every Nth row  |
 *   | squashAmount, squashFrequency | float, int | 1.0, 2 | Brick: width factor of every Nth row |
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

float blWhiteNoise1DValue(float w) { return blHashFloat1(w); }

float3 blWhiteNoise1DColor(float w) {
  return (float3)(blHashFloat1(w), blHashFloat2(w, 1.0f), blHashFloat2(w, 2.0f));
}

float blWhiteNoise2DValue(float3 vector) { return blHashFloat2(vector.x, vector.y); }

float3 blWhiteNoise2DColor(float3 vector) {
  return (float3)(blHashFloat2(vector.x, vector.y), blHashFloat3(vector.x, vector.y, 1.0f),
                  blHashFloat3(vector.x, vector.y, 2.0f));
}

float blWhiteNoise4DValue(float3 vector, float w) {
  return blHashFloat4(vector.x, vector.y, vector.z, w);
}

float3 blWhiteNoise4DColor(float3 vector, float w) {
  /* Cycles' hash_float4_to_float3: the other two channels hash permuted components. */
  return (float3)(blHashFloat4(vector.x, vector.y, vector.z, w),
                  blHashFloat4(vector.z, vector.x, w, vector.y),
                  blHashFloat4(w, vector.z, vector.y, vector.x));
}

float blWhiteNoise3DValue(float3 vector) { return blHashFloat3(vector.x, vector.y, vector.z); }

float3 blWhiteNoise3DColor(float3 vector) {
  return (float3)(blHashFloat3(vector.x, vector.y, vector.z),
                  blHashFloat4(vector.x, vector.y, vector.z, 1.0f),
                  blHashFloat4(vector.x, vector.y, vector.z, 2.0f));
}

/* Blender's brick_noise: a fast integer hash of a brick's number to [0, 1). */
float blBrickNoise(uint n) {
  n = (n + 1013U) & 0x7fffffffU;
  n = (n >> 13) ^ n;
  uint nn = (n * (n * n * 60493U + 19990303U) + 1376312589U) & 0x7fffffffU;
  return 0.5f * ((float)nn / 1073741824.0f);
}

/* The brick's tint (x) and the mortar mask (y) at p (already scaled). */
float2 blBrick(float3 p, float mortarSize, float mortarSmooth, float bias, float brickWidth,
               float rowHeight, float offsetAmount, int offsetFrequency, float squashAmount,
               int squashFrequency) {
  int rownum = (int)floor(p.y / rowHeight);
  float offset = 0.0f;
  if (offsetFrequency && squashFrequency) {
    brickWidth *= (rownum % squashFrequency) ? 1.0f : squashAmount;
    offset = (rownum % offsetFrequency) ? 0.0f : (brickWidth * offsetAmount);
  }
  int bricknum = (int)floor((p.x + offset) / brickWidth);
  float x = (p.x + offset) - brickWidth * (float)bricknum;
  float y = p.y - rowHeight * (float)rownum;
  float tint = clamp(blBrickNoise(((uint)rownum << 16) + (uint)(bricknum & 0xFFFF)) + bias, 0.0f,
                     1.0f);
  float minDist = fmin(fmin(x, y), fmin(brickWidth - x, rowHeight - y));
  float mortar;
  if (minDist >= mortarSize) {
    mortar = 0.0f;
  } else if (mortarSmooth == 0.0f) {
    mortar = 1.0f;
  } else {
    /* Blender's smoothstep of f, clamped: 1 past the blur. */
    float f = (1.0f - minDist / mortarSize) / mortarSmooth;
    float ff = f * f;
    mortar = f <= 0.0f ? 0.0f : (f >= 1.0f ? 1.0f : 3.0f * ff - 2.0f * ff * f);
  }
  return (float2)(tint, mortar);
}

float3 blBrickColor(float3 vector, float3 color1, float3 color2, float3 mortar, float scale,
                    float mortarSize, float mortarSmooth, float bias, float brickWidth,
                    float rowHeight, float offsetAmount, int offsetFrequency, float squashAmount,
                    int squashFrequency) {
  float2 b = blBrick(vector * scale, mortarSize, mortarSmooth, bias, brickWidth, rowHeight,
                     offsetAmount, offsetFrequency, squashAmount, squashFrequency);
  float3 c = color1;
  if (b.y != 1.0f)
    c = (1.0f - b.x) * color1 + b.x * color2;
  return c * (1.0f - b.y) + mortar * b.y;
}

float blBrickFac(float3 vector, float scale, float mortarSize, float mortarSmooth, float bias,
                 float brickWidth, float rowHeight, float offsetAmount, int offsetFrequency,
                 float squashAmount, int squashFrequency) {
  return blBrick(vector * scale, mortarSize, mortarSmooth, bias, brickWidth, rowHeight,
                 offsetAmount, offsetFrequency, squashAmount, squashFrequency).y;
}
