/* stripes.cl: stripes along an axis, drawn by the helper band that running text names here
 * (a mention, not a listing).
 *
 *   float3 stripeColor(float3 p, float3 colorA, float3 colorB)
 *   float stripes(float3 p, float width, int axis)
 *   void stripeInit(float *state)    (not a texture function: left out)
 *
 *   | name           | type   | default            | meaning       |
 *   |----------------|--------|--------------------|---------------|
 *   | p              | float3 | -                  | lookup point  |
 *   | width, axis    | float, int | 0.5, 2         | stripe width and axis |
 *   | colorA, colorB | float3 | (1, 0, 0), (0, 0, 1) | the two colours |
 */
float band(float x, float width) { return fmod(fabs(x), 2.0f * width) < width ? 1.0f : 0.0f; }

float stripes(float3 p, float width, int axis) {
  return band(axis == 0 ? p.x : (axis == 1 ? p.y : p.z), width);
}

void stripeInit(float *state) { *state = 0.0f; }

float3 stripeColor(float3 p, float3 colorA, float3 colorB) {
  return mix(colorA, colorB, stripes(p, 0.5f, 2));
}
