/* blender/curves.cl: Blender's Float Curve, RGB Curves and Vector Curves nodes (Cycles, Blender
 * 5.0), value for value.
 *
 * Cycles does not evaluate a curve mapping's Bezier curves while shading: Blender samples them
 * into a table of 257 entries at x = minX + i / 256 * (maxX - minX), where minX and maxX are
 * the smallest first and the largest last point x over the node's curves, and Cycles looks the
 * input up in that table, linearly between two entries; outside [minX, maxX] it extends the
 * table's first or last step (Extend Extrapolated) or holds its end value (Extend Horizontal).
 * The Blender exporter (scripts/blender_nodes.py) writes the table Blender makes, so these
 * functions only do Cycles' lookup and mix. RGB Curves' table already holds each channel's
 * curve applied after the combined (C) curve, as Blender builds it for Cycles; its Black and
 * White Levels change nothing in Cycles (a bake with levels 0.1 and 0.8 equals one without),
 * nor here.
 *
 *   float  blFloatCurve(float factor, float value, __global const float *table, int size,
 *                       float minX, float maxX, int extrapolate)
 *   float3 blRgbCurves(float fac, float3 color, __global const float4 *table, int size,
 *                      float minX, float maxX, int extrapolate)
 *   float3 blVectorCurves(float fac, float3 vector, __global const float4 *table, int size,
 *                         float minX, float maxX, int extrapolate)
 *
 * Each returns the input mixed with the curve's value: (1 - factor) * input + factor * curve.
 *
 * Parameters (Blender's defaults):
 *
 *   | name        | type                   | default       | meaning                          |
 *   |-------------|------------------------|---------------|----------------------------------|
 *   | factor, fac | float                  | 1.0           | how much of the curve's value    |
 *   | value       | float                  | 1.0           | Float Curve's input              |
 *   | color       | float3                 | 1, 1, 1       | RGB Curves' input (alpha unused) |
 *   | vector      | float3                 | 0, 0, 0       | Vector Curves' input             |
 *   | table       | __global const float* / float4* | 0.0, 1.0 | the sampled curves: one value (Float) or one RGB / XYZ row (w unused) per x; the default, two entries, is the identity |
 *   | size        | int                    | 2             | the table's entries (>= 2; the exporter writes 257) |
 *   | minX        | float                  | 0.0           | the x of the first entry (Vector Curves: -1) |
 *   | maxX        | float                  | 1.0           | the x of the last entry              |
 *   | extrapolate | int                    | 1             | 1 Extend Extrapolated, 0 Extend Horizontal |
 */

/* Cycles' ramp lookup of relative position f (0 at minX, 1 at maxX) in a table of size entries:
 * linear between the two entries around f; outside [0, 1] the end entry, or, extrapolating, the
 * end entry plus the end step times the distance past the end in entries. */
float blFloatCurveLookup(float f, __global const float *table, int size, int extrapolate) {
  if (extrapolate && f < 0.0f)
    return table[0] + (table[0] - table[1]) * -f * (float)(size - 1);
  if (extrapolate && f > 1.0f)
    return table[size - 1] + (table[size - 1] - table[size - 2]) * (f - 1.0f) * (float)(size - 1);
  f = clamp(f, 0.0f, 1.0f) * (float)(size - 1);
  int i = clamp((int)f, 0, size - 1);
  float t = f - (float)i;
  return t > 0.0f ? (1.0f - t) * table[i] + t * table[i + 1] : table[i];
}

/* The same over a table of RGB or XYZ rows (w unused; all three channels at f). */
float3 blCurveRowsLookup(float f, __global const float4 *table, int size, int extrapolate) {
  if (extrapolate && f < 0.0f)
    return (table[0] + (table[0] - table[1]) * -f * (float)(size - 1)).xyz;
  if (extrapolate && f > 1.0f)
    return (table[size - 1] + (table[size - 1] - table[size - 2]) * (f - 1.0f) *
            (float)(size - 1)).xyz;
  f = clamp(f, 0.0f, 1.0f) * (float)(size - 1);
  int i = clamp((int)f, 0, size - 1);
  float t = f - (float)i;
  return (t > 0.0f ? (1.0f - t) * table[i] + t * table[i + 1] : table[i]).xyz;
}

float blFloatCurve(float factor, float value, __global const float *table, int size, float minX,
                   float maxX, int extrapolate) {
  float curve = blFloatCurveLookup((value - minX) / (maxX - minX), table, size, extrapolate);
  return (1.0f - factor) * value + factor * curve;
}

/* Each channel of in through its own column of the table (red through the red curve ...). */
float3 blCurvesRows(float fac, float3 in, __global const float4 *table, int size, float minX,
                    float maxX, int extrapolate) {
  float3 f = (in - (float3)(minX)) / (maxX - minX);
  float3 curve = (float3)(blCurveRowsLookup(f.x, table, size, extrapolate).x,
                          blCurveRowsLookup(f.y, table, size, extrapolate).y,
                          blCurveRowsLookup(f.z, table, size, extrapolate).z);
  return (1.0f - fac) * in + fac * curve;
}

float3 blRgbCurves(float fac, float3 color, __global const float4 *table, int size, float minX,
                   float maxX, int extrapolate) {
  return blCurvesRows(fac, color, table, size, minX, maxX, extrapolate);
}

float3 blVectorCurves(float fac, float3 vector, __global const float4 *table, int size,
                      float minX, float maxX, int extrapolate) {
  return blCurvesRows(fac, vector, table, size, minX, maxX, extrapolate);
}
