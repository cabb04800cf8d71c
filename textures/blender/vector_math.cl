/* blender/vector_math.cl: Blender's Vector Math node (Cycles, Blender 5.0), every operation.
 *
 * The node has two outputs: Vector (most operations) and Value (Dot Product, Distance, Length);
 * the output an operation does not produce is 0.
 *
 *   float3 blVectorMath(float3 a, float3 b, float3 c, float scale, int operation)
 *   float  blVectorMathValue(float3 a, float3 b, float3 c, float scale, int operation)
 *
 * Also the Mapping node and Map Range in Vector mode:
 *
 *   float3 blMapping(float3 vector, float3 location, float3 rotation, float3 scale,
 *                    int mappingType)         0 Point, 1 Texture, 2 Vector, 3 Normal;
 *                                             rotation: XYZ Euler angles in radians
 *   float3 blMapRangeVector(float3 vector, float3 fromMin, float3 fromMax, float3 toMin,
 *                           float3 toMax, float3 steps, int interpolation, int useClamp)
 *                                             per component; as blMapRange (math.cl), but a
 *                                             zero-width interval gives 0, not the whole result
 *
 * Parameters (Blender's defaults):
 *
 *   | name      | type   | default | meaning                                                   |
 *   |-----------|--------|---------|-----------------------------------------------------------|
 *   | a, b, c   | float3 | 0       | the three Vector inputs (c: Multiply Add, Wrap, Faceforward) |
 *   | scale     | float  | 1.0     | Scale's factor; Refract's IOR                             |
 *   | operation | int    | 0       | 0 Add, 1 Subtract, 2 Multiply, 3 Divide, 4 Cross Product, 5 Project, |
 *   |           |        |         | 6 Reflect, 7 Dot Product, 8 Distance, 9 Length, 10 Scale, 11 Normalize, |
 *   |           |        |         | 12 Snap, 13 Floor, 14 Ceil, 15 Modulo, 16 Fraction, 17 Absolute, |
 *   |           |        |         | 18 Minimum, 19 Maximum, 20 Wrap, 21 Sine, 22 Cosine, 23 Tangent, |
 *   |           |        |         | 24 Refract, 25 Faceforward, 26 Multiply Add, 27 Power, 28 Sign |
 *   |           |        |         | (Cycles' numbering)                                       |
 */

float blVmSafeDivide(float a, float b) { return b != 0.0f ? a / b : 0.0f; }

float3 blVmSafeDivide3(float3 a, float3 b) {
  return (float3)(blVmSafeDivide(a.x, b.x), blVmSafeDivide(a.y, b.y), blVmSafeDivide(a.z, b.z));
}

float blVmDot(float3 a, float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

float blVmLength(float3 a) { return sqrt(blVmDot(a, a)); }

float blVmModulo(float a, float b) { return b != 0.0f ? fmod(a, b) : 0.0f; }

float blVmWrap(float value, float maximum, float minimum) {
  float range = maximum - minimum;
  return range != 0.0f ? value - range * floor((value - minimum) / range) : minimum;
}

float blVmPow(float a, float b) {
  if (a < 0.0f && b != (float)(int)b)
    return 0.0f;
  return pow(a, b);
}

float blVmSign(float a) { return a == 0.0f ? 0.0f : (a < 0.0f ? -1.0f : 1.0f); }

float3 blVmNormalize(float3 a) {
  float t = blVmLength(a);
  return t != 0.0f ? a * (1.0f / t) : a;
}

float3 blVectorMath(float3 a, float3 b, float3 c, float scale, int operation) {
  switch (operation) {
  case 0: return a + b;
  case 1: return a - b;
  case 2: return a * b;
  case 3: return blVmSafeDivide3(a, b);
  case 4: return (float3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  case 5: {
    float lenSquared = blVmDot(b, b);
    return lenSquared != 0.0f ? (blVmDot(a, b) / lenSquared) * b : (float3)(0.0f);
  }
  case 6: {
    float3 n = b / blVmLength(b);
    return a - 2.0f * n * blVmDot(a, n);
  }
  case 10: return a * scale;
  case 11: return blVmNormalize(a);
  case 12: return floor(blVmSafeDivide3(a, b)) * b;
  case 13: return floor(a);
  case 14: return ceil(a);
  case 15: return (float3)(blVmModulo(a.x, b.x), blVmModulo(a.y, b.y), blVmModulo(a.z, b.z));
  case 16: return a - floor(a);
  case 17: return fabs(a);
  case 18: return fmin(a, b);
  case 19: return fmax(a, b);
  case 20:
    return (float3)(blVmWrap(a.x, b.x, c.x), blVmWrap(a.y, b.y, c.y), blVmWrap(a.z, b.z, c.z));
  case 21: return (float3)(sin(a.x), sin(a.y), sin(a.z));
  case 22: return (float3)(cos(a.x), cos(a.y), cos(a.z));
  case 23: return (float3)(tan(a.x), tan(a.y), tan(a.z));
  case 24: {
    float3 n = b / blVmLength(b);
    float d = blVmDot(n, a);
    float k = 1.0f - scale * scale * (1.0f - d * d);
    return k < 0.0f ? (float3)(0.0f) : scale * a - (scale * d + sqrt(k)) * n;
  }
  case 25: return blVmDot(c, b) < 0.0f ? a : -a;
  case 26: return a * b + c;
  case 27: return (float3)(blVmPow(a.x, b.x), blVmPow(a.y, b.y), blVmPow(a.z, b.z));
  case 28: return (float3)(blVmSign(a.x), blVmSign(a.y), blVmSign(a.z));
  default: return (float3)(0.0f);
  }
}

float blVectorMathValue(float3 a, float3 b, float3 c, float scale, int operation) {
  if (operation == 7)
    return blVmDot(a, b);
  if (operation == 8)
    return blVmLength(a - b);
  if (operation == 9)
    return blVmLength(a);
  return 0.0f;
}

/* The rows of Blender's XYZ Euler rotation matrix (Cycles' euler_to_transform). */
void blEulerRows(float3 euler, float3 *rx, float3 *ry, float3 *rz) {
  float cx = cos(euler.x), cy = cos(euler.y), cz = cos(euler.z);
  float sx = sin(euler.x), sy = sin(euler.y), sz = sin(euler.z);
  *rx = (float3)(cy * cz, sy * sx * cz - cx * sz, sy * cx * cz + sx * sz);
  *ry = (float3)(cy * sz, sy * sx * sz + cx * cz, sy * cx * sz - sx * cz);
  *rz = (float3)(-sy, cy * sx, cy * cx);
}

float3 blMapping(float3 vector, float3 location, float3 rotation, float3 scale, int mappingType) {
  float3 rx, ry, rz;
  blEulerRows(rotation, &rx, &ry, &rz);
  if (mappingType == 1) {
    /* Texture: the inverse of Point (transposed rotation), so textures move with the object. */
    float3 v = vector - location;
    float3 cx = (float3)(rx.x, ry.x, rz.x), cy = (float3)(rx.y, ry.y, rz.y);
    float3 cz = (float3)(rx.z, ry.z, rz.z);
    return blVmSafeDivide3((float3)(blVmDot(cx, v), blVmDot(cy, v), blVmDot(cz, v)), scale);
  }
  float3 v = mappingType == 3 ? blVmSafeDivide3(vector, scale) : vector * scale;
  float3 r = (float3)(blVmDot(rx, v), blVmDot(ry, v), blVmDot(rz, v));
  if (mappingType == 0)
    return r + location;
  if (mappingType == 3)
    return blVmNormalize(r);
  return r;
}

float blMapRangeStep(float factor, float steps) {
  return steps > 0.0f ? floor(factor * (steps + 1.0f)) / steps : 0.0f;
}

float blMapRangeClamp(float value, float a, float b) {
  return a > b ? fmin(fmax(value, b), a) : fmin(fmax(value, a), b);
}

float3 blMapRangeVector(float3 vector, float3 fromMin, float3 fromMax, float3 toMin, float3 toMax,
                        float3 steps, int interpolation, int useClamp) {
  float3 factor = blVmSafeDivide3(vector - fromMin, fromMax - fromMin);
  if (interpolation == 1) {
    factor = (float3)(blMapRangeStep(factor.x, steps.x), blMapRangeStep(factor.y, steps.y),
                      blMapRangeStep(factor.z, steps.z));
  } else if (interpolation == 2) {
    factor = clamp(factor, 0.0f, 1.0f);
    factor = ((float3)(3.0f) - 2.0f * factor) * (factor * factor);
  } else if (interpolation == 3) {
    factor = clamp(factor, 0.0f, 1.0f);
    factor = factor * factor * factor * (factor * (factor * 6.0f - 15.0f) + 10.0f);
  }
  float3 result = toMin + factor * (toMax - toMin);
  if (useClamp && interpolation <= 1)
    result = (float3)(blMapRangeClamp(result.x, toMin.x, toMax.x),
                      blMapRangeClamp(result.y, toMin.y, toMax.y),
                      blMapRangeClamp(result.z, toMin.z, toMax.z));
  return result;
}
