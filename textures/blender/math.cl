/* blender/math.cl: Blender's Math, Map Range (Float) and Clamp nodes (Cycles, Blender 5.0).
 *
 * The "safe" variants are Blender's: division, modulo and logarithm by zero give 0, sqrt of a
 * negative gives 0, arcsine/arccosine clamp their argument, a negative base with a non-integer
 * exponent gives 0.
 *
 *   float blMath(float a, float b, float c, int operation, int useClamp)
 *   float blMapRange(float value, float fromMin, float fromMax, float toMin, float toMax,
 *                    float steps, int interpolation, int useClamp)
 *   float blClamp(float value, float minimum, float maximum, int clampType)
 *
 * Parameters (Blender's defaults):
 *
 *   | name          | type  | default | meaning                                               |
 *   |---------------|-------|---------|-------------------------------------------------------|
 *   | a, b, c       | float | 0.5     | the Math node's three Value inputs (c: Multiply Add, Wrap, Compare, Smooth Min/Max) |
 *   | operation     | int   | 0       | 0 Add, 1 Subtract, 2 Multiply, 3 Divide, 4 Sine, 5 Cosine, 6 Tangent, 7 Arcsine, |
 *   |               |       |         | 8 Arccosine, 9 Arctangent, 10 Power, 11 Logarithm (base b), 12 Minimum, 13 Maximum, |
 *   |               |       |         | 14 Round, 15 Less Than, 16 Greater Than, 17 Truncated Modulo, 18 Absolute, |
 *   |               |       |         | 19 Arctan2, 20 Floor, 21 Ceil, 22 Fraction, 23 Square Root, 24 Inverse Square Root, |
 *   |               |       |         | 25 Sign, 26 Exponent, 27 To Radians, 28 To Degrees, 29 Sinh, 30 Cosh, 31 Tanh, |
 *   |               |       |         | 32 Truncate, 33 Snap, 34 Wrap, 35 Compare, 36 Multiply Add, 37 Ping-Pong, |
 *   |               |       |         | 38 Smooth Minimum, 39 Smooth Maximum, 40 Floored Modulo (Cycles' numbering) |
 *   | useClamp      | int   | 0       | 1 clamps the result to [0, 1] (Map Range: to [toMin, toMax], Linear and Stepped only) |
 *   | value         | float | 1.0     | Map Range's and Clamp's input                         |
 *   | fromMin, fromMax | float | 0.0, 1.0 | Map Range's source interval                      |
 *   | toMin, toMax  | float | 0.0, 1.0 | Map Range's target interval                          |
 *   | steps         | float | 4.0     | Map Range Stepped only                                |
 *   | interpolation | int   | 0       | Map Range: 0 Linear, 1 Stepped, 2 Smooth Step, 3 Smoother Step |
 *   | minimum, maximum | float | 0.0, 1.0 | Clamp's interval                                |
 *   | clampType     | int   | 0       | Clamp: 0 Min Max, 1 Range (an inverted interval is swapped) |
 */

float blSafeDivide(float a, float b) { return b != 0.0f ? a / b : 0.0f; }

float blSafeModulo(float a, float b) { return b != 0.0f ? fmod(a, b) : 0.0f; }

float blSafeFlooredModulo(float a, float b) { return b != 0.0f ? a - floor(a / b) * b : 0.0f; }

float blSafePow(float a, float b) {
  if (a < 0.0f && b != (float)(int)b)
    return 0.0f;
  return pow(a, b);
}

float blSafeLog(float a, float b) {
  if (a <= 0.0f || b <= 0.0f)
    return 0.0f;
  return blSafeDivide(log(a), log(b));
}

float blWrap(float value, float maximum, float minimum) {
  float range = maximum - minimum;
  return range != 0.0f ? value - range * floor((value - minimum) / range) : minimum;
}

float blPingPong(float a, float b) {
  if (b == 0.0f)
    return 0.0f;
  float x = (a - b) / (b * 2.0f);
  return fabs((x - floor(x)) * b * 2.0f - b);
}

float blSmoothMin(float a, float b, float k) {
  if (k == 0.0f)
    return fmin(a, b);
  float h = fmax(k - fabs(a - b), 0.0f) / k;
  return fmin(a, b) - h * h * h * k * (1.0f / 6.0f);
}

float blSaturate(float x) { return fmin(fmax(x, 0.0f), 1.0f); }

float blMathOp(float a, float b, float c, int op) {
  switch (op) {
  case 0: return a + b;
  case 1: return a - b;
  case 2: return a * b;
  case 3: return blSafeDivide(a, b);
  case 4: return sin(a);
  case 5: return cos(a);
  case 6: return tan(a);
  case 7: return asin(fmin(fmax(a, -1.0f), 1.0f));
  case 8: return acos(fmin(fmax(a, -1.0f), 1.0f));
  case 9: return atan(a);
  case 10: return blSafePow(a, b);
  case 11: return blSafeLog(a, b);
  case 12: return fmin(a, b);
  case 13: return fmax(a, b);
  case 14: return floor(a + 0.5f);
  case 15: return a < b ? 1.0f : 0.0f;
  case 16: return a > b ? 1.0f : 0.0f;
  case 17: return blSafeModulo(a, b);
  case 18: return fabs(a);
  case 19: return atan2(a, b);
  case 20: return floor(a);
  case 21: return ceil(a);
  case 22: return a - floor(a);
  case 23: return sqrt(fmax(a, 0.0f));
  case 24: return a > 0.0f ? 1.0f / sqrt(a) : 0.0f;
  case 25: return a == 0.0f ? 0.0f : (a < 0.0f ? -1.0f : 1.0f);
  case 26: return exp(a);
  case 27: return a * (3.14159265358979323846f / 180.0f);
  case 28: return a * (180.0f / 3.14159265358979323846f);
  case 29: return sinh(a);
  case 30: return cosh(a);
  case 31: return tanh(a);
  case 32: return a >= 0.0f ? floor(a) : ceil(a);
  case 33: return floor(blSafeDivide(a, b)) * b;
  case 34: return blWrap(a, b, c);
  case 35: return (a == b || fabs(a - b) <= fmax(c, 1.192092896e-07f /* FLT_EPSILON */)) ? 1.0f : 0.0f;
  case 36: return a * b + c;
  case 37: return blPingPong(a, b);
  case 38: return blSmoothMin(a, b, c);
  case 39: return -blSmoothMin(-a, -b, c);
  case 40: return blSafeFlooredModulo(a, b);
  default: return 0.0f;
  }
}

float blMath(float a, float b, float c, int operation, int useClamp) {
  float r = blMathOp(a, b, c, operation);
  return useClamp ? blSaturate(r) : r;
}

/* Cycles' smoothstep: 0 below edge0, 1 from edge1 on, (3 - 2t) t^2 between. */
float blSmoothstep(float edge0, float edge1, float x) {
  if (x < edge0)
    return 0.0f;
  if (x >= edge1)
    return 1.0f;
  float t = (x - edge0) / (edge1 - edge0);
  return (3.0f - 2.0f * t) * (t * t);
}

float blSmootherstep(float edge0, float edge1, float x) {
  x = fmin(fmax(blSafeDivide(x - edge0, edge1 - edge0), 0.0f), 1.0f);
  return x * x * x * (x * (x * 6.0f - 15.0f) + 10.0f);
}

float blClampRange(float value, float a, float b) {
  return a > b ? fmin(fmax(value, b), a) : fmin(fmax(value, a), b);
}

float blMapRange(float value, float fromMin, float fromMax, float toMin, float toMax,
                 float steps, int interpolation, int useClamp) {
  if (fromMax == fromMin)
    return 0.0f;
  float factor;
  if (interpolation == 1) {
    factor = (value - fromMin) / (fromMax - fromMin);
    factor = steps > 0.0f ? floor(factor * (steps + 1.0f)) / steps : 0.0f;
  } else if (interpolation == 2) {
    factor = fromMin > fromMax ? 1.0f - blSmoothstep(fromMax, fromMin, value)
                               : blSmoothstep(fromMin, fromMax, value);
  } else if (interpolation == 3) {
    factor = fromMin > fromMax ? 1.0f - blSmootherstep(fromMax, fromMin, value)
                               : blSmootherstep(fromMin, fromMax, value);
  } else {
    factor = (value - fromMin) / (fromMax - fromMin);
  }
  float result = toMin + factor * (toMax - toMin);
  if (useClamp && interpolation <= 1)
    result = blClampRange(result, toMin, toMax);
  return result;
}

float blClamp(float value, float minimum, float maximum, int clampType) {
  if (clampType == 1)
    return blClampRange(value, minimum, maximum);
  return fmin(fmax(value, minimum), maximum);
}
