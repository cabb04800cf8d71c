/* mix.cl: blending two values or colours by a factor (Blender's MixRGB node).
 *
 * Texture functions (graph "fn" names):
 *
 *   float  mixValue(float a, float b, float t)               a + (b - a) * clamp(t, 0, 1)
 *   float3 mixColor(float3 a, float3 b, float t)             the same, per channel
 *   float3 blendColor(float3 a, float3 b, float t, int mode) mixColor(a, blend_mode(a, b), t)
 *
 * Parameters:
 *
 *   | name | type          | default | range | meaning                                       |
 *   |------|---------------|---------|-------|-----------------------------------------------|
 *   | a    | float/float3  | -       | any   | the base (t = 0)                              |
 *   | b    | float/float3  | -       | any   | the layer (t = 1)                             |
 *   | t    | float         | 0.5     | 0..1  | blend factor, clamped to [0, 1]               |
 *   | mode | int           | 0       | 0..7  | 0 mix (b), 1 multiply (a*b), 2 add (a+b), 3 screen (1-(1-a)(1-b)), 4 overlay, 5 difference (abs(a-b)), 6 darken (min), 7 lighten (max); any other value acts as 0 |
 *
 * Overlay is per channel: 2ab where a < 0.5, else 1 - 2(1-a)(1-b).
 */

float clamp01(float x) { return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }

float blendChannel(float a, float b, int mode) {
  switch (mode) {
  case 1: return a * b;
  case 2: return a + b;
  case 3: return 1.0f - (1.0f - a) * (1.0f - b);
  case 4: return a < 0.5f ? 2.0f * a * b : 1.0f - 2.0f * (1.0f - a) * (1.0f - b);
  case 5: return fabs(a - b);
  case 6: return fmin(a, b);
  case 7: return fmax(a, b);
  default: return b;
  }
}

float mixValue(float a, float b, float t) { return a + (b - a) * clamp01(t); }

float3 mixColor(float3 a, float3 b, float t) {
  float w = clamp01(t);
  return (float3)(a.x + (b.x - a.x) * w, a.y + (b.y - a.y) * w, a.z + (b.z - a.z) * w);
}

float3 blendColor(float3 a, float3 b, float t, int mode) {
  float3 layer = (float3)(blendChannel(a.x, b.x, mode), blendChannel(a.y, b.y, mode),
                          blendChannel(a.z, b.z, mode));
  return mixColor(a, layer, t);
}
