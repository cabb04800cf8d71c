/* basic.cl: small textures that exercise every parameter kind for the codegen tests.
 *   wave(float3 p, float scale, int octaves)          float    sum of sines over octaves
 *   tint(float t, float3 lo, float3 hi)               float3   mix(lo, hi, t)
 *   ramp(float t, __global const float4* stops, int n) float4  piecewise-linear colour ramp
 *   warp(float2 uv, float2 offset, float amount)      float2   a bent uv
 *   mask(float ao, float4 weights, float threshold)   float    smoothstep of AO and weights
 *   image(sam2D img, float2 uv)                        float4   a texture fetch
 */
static float hash01(float x) { return fract(x * 0.6180339f, &x); }

float wave(float3 p, float scale, int octaves) {
  float sum = 0.0f, amp = 0.5f;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * sin(dot(p, (float3)(1.0f, 1.7f, 2.3f)) * scale);
    scale *= 2.0f;
    amp *= 0.5f;
  }
  return sum + 0.01f * hash01((float)octaves);
}

float3 tint(float t, float3 lo, float3 hi) { return mix(lo, hi, clamp(t, 0.0f, 1.0f)); }

float4 ramp(float t, __global const float4 *stops, int n) {
  float4 c = (float4)(stops[0].yzw, 1.0f);
  for (int i = 1; i < n; ++i) {
    float k = smoothstep(stops[i - 1].x, stops[i].x, t);
    c = mix(c, (float4)(stops[i].yzw, 1.0f), k);
  }
  return c;
}

float2 warp(float2 uv, float2 offset, float amount) {
  return uv + offset * amount + (float2)(sin(uv.y * 3.0f), cos(uv.x * 3.0f)) * 0.1f;
}

float mask(float ao, float4 weights, float threshold) {
  float3 n = readAttr("Normal");
  return smoothstep(threshold - 0.1f, threshold + 0.1f, ao * weights.x + n.y * weights.y) +
         weights.z * readSetting("Time") + weights.w;
}

float4 image(sam2D img, float2 uv) { return tex2D(img, uv); }
