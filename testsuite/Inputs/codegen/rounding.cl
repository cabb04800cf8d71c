/* rounding.cl: floor, ceil and trunc, scalar and on vectors, at negative zeros, tiny and large
 * values (codegen/device-rounding.test). The input is built at run time from the hit's position,
 * so that nothing folds at compile time.
 *
 *   float4 roundingZeros(float3 p)     floor(-0.0), ceil(-0.25), trunc(-0.5), ceil(-0.75)
 *   float4 roundingEdges(float3 p)     floor(-2^-30), ceil(8388607.5), trunc(-8388607.5), floor(1e10)
 *   float4 roundingVector(float3 p)    floor, ceil, trunc of a float4 and a float3, summed
 */
float4 roundingZeros(float3 p) {
  float k = fabs(p.x) * 0.0f + 1.0f; /* 1.0 at run time */
  return (float4)(floor(-0.0f * k), ceil(-0.25f * k), trunc(-0.5f * k), ceil(-0.75f * k));
}

float4 roundingEdges(float3 p) {
  float k = fabs(p.x) * 0.0f + 1.0f;
  return (float4)(floor(-9.3132257e-10f * k), ceil(8388607.5f * k), trunc(-8388607.5f * k),
                  floor(1e10f * k));
}

float4 roundingVector(float3 p) {
  float4 v = (float4)(-2.5f, 0.5f, -1e-20f, 3.75f) * (fabs(p.x) * 0.0f + 1.0f) + (float4)(p * 8.0f, 0.0f);
  float3 w = v.xyz * 0.5f;
  return floor(v) * 1000.0f + ceil(v) * 100.0f + trunc(v) * 10.0f +
         (float4)(floor(w) + ceil(w) + trunc(w), 0.0f);
}
