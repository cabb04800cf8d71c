/* Light and heavy texture functions for the superinstruction tests (superinstructions.test). */

/* Light: a few statements each. */
float scaleAdd(float x, float a, float b) { return x * a + b; }

float3 tint3(float t, float3 c) { return c * t; }

/* A float4 from a float3 and a float: a float2..4 parameter that a float feeds is broadcast. */
float4 withAlpha(float4 rgba, float alpha) { return (float4)(rgba.xyz, alpha); }

/* Heavy: a loop of 100 trips (the front end's cost counts its body 100 times). */
float heavy(float3 p, float k) {
  float s = 0.0f;
  for (int i = 0; i < 100; ++i)
    s += sin(p.x * k + (float)i) * cos(p.y * k - (float)i) + p.z;
  return s * 0.01f;
}
