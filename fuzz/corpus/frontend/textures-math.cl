/* math.cl: arithmetic on values and colours by an operation code (Blender's Math node), and
 * range remapping.
 *
 * Texture functions (graph "fn" names):
 *
 *   float  mathValue(float a, float b, int op)     op(a, b)
 *   float3 mathColor(float3 a, float3 b, int op)   op per channel
 *   float  mapRange(float x, float fromMin, float fromMax, float toMin, float toMax, int clampResult)
 *       linear map of [fromMin, fromMax] onto [toMin, toMax]; clampResult != 0 clamps the
 *       result into the target interval; fromMin == fromMax gives toMin.
 *
 * Operation codes (op, int):
 *
 *   | op | name        | result                         | op | name       | result               |
 *   |----|-------------|--------------------------------|----|------------|----------------------|
 *   | 0  | add         | a + b                          | 8  | greater    | a > b ? 1 : 0        |
 *   | 1  | subtract    | a - b                          | 9  | modulo     | a - b * floor(a / b) (0 if b == 0), sign of b |
 *   | 2  | multiply    | a * b                          | 10 | absolute   | abs(a)               |
 *   | 3  | divide      | a / b, 0 where b == 0          | 11 | sqrt       | sqrt(max(a, 0))      |
 *   | 4  | power       | pow(max(a, 0), b)              | 12 | sine       | sin(a)               |
 *   | 5  | minimum     | min(a, b)                      | 13 | cosine     | cos(a)               |
 *   | 6  | maximum     | max(a, b)                      | 14 | step       | a >= b ? 1 : 0       |
 *   | 7  | less        | a < b ? 1 : 0                  | 15 | clamp01    | clamp(a, 0, 1)       |
 *
 * Any other op gives a unchanged. Unary operations ignore b.
 */

float mathOp(float a, float b, int op) {
  switch (op) {
  case 0: return a + b;
  case 1: return a - b;
  case 2: return a * b;
  case 3: return b == 0.0f ? 0.0f : a / b;
  case 4: return a <= 0.0f ? 0.0f : pow(a, b);
  case 5: return fmin(a, b);
  case 6: return fmax(a, b);
  case 7: return a < b ? 1.0f : 0.0f;
  case 8: return a > b ? 1.0f : 0.0f;
  case 9: return b == 0.0f ? 0.0f : a - b * floor(a / b);
  case 10: return fabs(a);
  case 11: return a <= 0.0f ? 0.0f : sqrt(a);
  case 12: return sin(a);
  case 13: return cos(a);
  case 14: return a >= b ? 1.0f : 0.0f;
  case 15: return a < 0.0f ? 0.0f : (a > 1.0f ? 1.0f : a);
  default: return a;
  }
}

float mathValue(float a, float b, int op) { return mathOp(a, b, op); }

float3 mathColor(float3 a, float3 b, int op) {
  return (float3)(mathOp(a.x, b.x, op), mathOp(a.y, b.y, op), mathOp(a.z, b.z, op));
}

float mapRange(float x, float fromMin, float fromMax, float toMin, float toMax, int clampResult) {
  if (fromMax == fromMin)
    return toMin;
  float r = toMin + (x - fromMin) / (fromMax - fromMin) * (toMax - toMin);
  if (clampResult != 0) {
    float lo = fmin(toMin, toMax), hi = fmax(toMin, toMax);
    r = r < lo ? lo : (r > hi ? hi : r);
  }
  return r;
}
