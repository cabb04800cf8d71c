/* random_nodes.cl: the texture functions that random_graphs.py wires into random DAGs. Between
 * them they take every parameter kind (float, int, float2..4, sam2D, __global const arrays of
 * float..float4 and int) and return every value type; they read attributes and settings
 * themselves too. Every function keeps its result bounded and its gain below about 1, so that
 * float rounding differences between the device and the host do not grow along deep chains
 * (the equivalence tests compare at 1e-5).
 */

float rnd_blend(float a, float b, float k) {
  return 0.5f * a + 0.3f * b * k + 0.1f * sin(a + b);
}

float2 rnd_swirl(float2 uv, float s, int n) {
  return (float2)(sin(uv.x + s), cos(uv.y * 0.5f)) * 0.8f + (float)n * 0.05f;
}

float3 rnd_mix3(float3 p, float3 q, float w) {
  return mix(p, q, clamp(w, 0.0f, 1.0f)) * 0.9f + cross(p, q) * 0.05f;
}

float4 rnd_shade(float4 c, float2 uv, float t) {
  return c * 0.7f + (float4)(uv, t, 1.0f) * 0.2f;
}

float rnd_len(float3 p, float4 c) {
  return 0.3f * sqrt(dot(p, p) + 0.01f) - 0.2f * dot(c.xy, c.zw);
}

float rnd_weights(float t, __global const float4 *w, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i)
    s += w[i].x * t * 0.25f + w[i].y * sin(w[i].z * t) * 0.25f + w[i].w * 0.1f;
  return clamp(s, -2.0f, 2.0f);
}

float3 rnd_points(float3 p, __global const float3 *pts, int n) {
  float3 best = pts[0];
  float bd = distance(p, pts[0]);
  for (int i = 1; i < n; ++i) {
    float d = distance(p, pts[i]);
    best = d < bd ? pts[i] : best;
    bd = fmin(d, bd);
  }
  return best * 0.5f + p * 0.25f;
}

float2 rnd_curve(float x, __global const float2 *pts, __global const float *gains, int n) {
  float2 acc = (float2)(0.0f);
  for (int i = 0; i < n; ++i)
    acc += pts[i] * gains[i] * smoothstep(-1.0f, 1.0f, x - 0.1f * (float)i);
  return clamp(acc * 0.5f, -2.0f, 2.0f);
}

float rnd_pick(float x, __global const int *table, int n) {
  int i = clamp((int)floor((x + 2.0f) * 2.0f), 0, n - 1);
  return 0.25f * (float)table[i] + 0.1f * x;
}

float rnd_surface(float a, float3 dir) {
  float3 n = readAttr("Normal");
  float2 uv = readAttr("TexCoord0");
  return 0.4f * a + 0.3f * dot(n, dir) + 0.1f * uv.x + 0.05f * readSetting("Time") +
         0.02f * (float)readSetting("Frame");
}

float4 rnd_image(sam2D img, float2 uv) {
  return tex2D(img, uv);
}
