/* ramp.cl: colour and value ramps over an array of stops (Blender's ColorRamp node).
 *
 * The stops come from the graph as a literal array of arrays, sorted by position t:
 *   "stops": [[0.0, 0.35, 0.12, 0.05], [0.6, 0.55, 0.25, 0.08], [1.0, 0.2, 0.1, 0.05]]
 * Below the first stop the ramp gives the first stop's value, above the last the last's.
 *
 * Texture functions (graph "fn" names):
 *
 *   float3 colorRamp(float t, __global const float4* stops, int count, int interpolation)
 *       stops are rows (t, r, g, b); returns the colour at t.
 *   float valueRamp(float t, __global const float2* stops, int count, int interpolation)
 *       stops are rows (t, v); returns the value at t (a remapping curve for masks).
 *
 * Parameters:
 *
 *   | name          | type                   | default | range     | meaning                     |
 *   |---------------|------------------------|---------|-----------|-----------------------------|
 *   | t             | float                  | -       | any       | ramp position, usually a node |
 *   | stops         | __global const float4* / float2* | - | 1..64 rows, t ascending | the stops |
 *   | count         | int                    | -       | 1..len    | number of stops used; <= 0 gives 0 |
 *   | interpolation | int                    | 0       | 0, 1, 2   | 0 linear, 1 constant (the value of the last stop at or below t), 2 ease (smoothstep between stops) |
 *
 * Stops that are not ascending are not an error: each segment [t_i, t_i+1] with
 * t_i+1 <= t_i is skipped.
 */

/* The blend factor in [0, 1] of t inside the segment [t0, t1] (t0 < t1), shaped by the
 * interpolation mode (constant: always the segment's start). */
float rampLocate(float t, float t0, float t1, int interpolation) {
  if (interpolation == 1)
    return 0.0f;
  float w = (t - t0) / (t1 - t0);
  w = w < 0.0f ? 0.0f : (w > 1.0f ? 1.0f : w);
  if (interpolation == 2)
    w = w * w * (3.0f - 2.0f * w);
  return w;
}

float3 colorRamp(float t, __global const float4 *stops, int count, int interpolation) {
  if (count <= 0)
    return (float3)(0.0f, 0.0f, 0.0f);
  float4 first = stops[0];
  if (count == 1 || t <= first.x)
    return (float3)(first.y, first.z, first.w);
  for (int i = 0; i + 1 < count; ++i) {
    float4 a = stops[i];
    float4 b = stops[i + 1];
    if (t < b.x && b.x > a.x) {
      float w = rampLocate(t, a.x, b.x, interpolation);
      return (float3)(a.y + (b.y - a.y) * w, a.z + (b.z - a.z) * w, a.w + (b.w - a.w) * w);
    }
  }
  float4 last = stops[count - 1];
  return (float3)(last.y, last.z, last.w);
}

float valueRamp(float t, __global const float2 *stops, int count, int interpolation) {
  if (count <= 0)
    return 0.0f;
  float2 first = stops[0];
  if (count == 1 || t <= first.x)
    return first.y;
  for (int i = 0; i + 1 < count; ++i) {
    float2 a = stops[i];
    float2 b = stops[i + 1];
    if (t < b.x && b.x > a.x)
      return a.y + (b.y - a.y) * rampLocate(t, a.x, b.x, interpolation);
  }
  return stops[count - 1].y;
}
