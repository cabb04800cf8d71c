/* hoist.cl: texture functions with declarations that depend on constant parameters only
 * (texcc computes them once per material in shape mode, docs/frontend.md "Hoisting"), and
 * declarations that look alike but may not be hoisted. */

#define TURN(a) ((a) * 0.5f)

float helperScale(float x) { return x * 2.0f; }

/* c and s: hoisted (from angle); u and w read p. */
float3 turn(float3 p, float angle, float stretch) {
  float c = cos(angle), s = sin(angle);
  float k = 1.0f / fmax(stretch, 1.0f);
  float u = c * p.x + s * p.z;
  float w = -s * p.x + c * p.z;
  return (float3)(u * k, p.y, w);
}

/* dir (a float3), n (an int) and m (from a macro and an earlier hoisted value) are hoisted;
 * twice has no call, scaled calls a user function, varying reads p, bumped reads a parameter
 * the body changes, per divides integers (a guarded division would run unguarded once per
 * material): none of these five is. */
float shade(float3 p, float3 axis, int octaves, float gain, float bump) {
  float3 dir = normalize(axis);
  int n = clamp(octaves, 1, 8);
  float twice = gain * 2.0f;
  float scaled = helperScale(gain);
  float varying = sin(p.x);
  float bumped = cos(bump);
  int per = abs(12 / octaves);
  float m = sqrt(TURN(gain)) + (float)n;
  bump += 1.0f;
  float sum = 0.0f;
  for (int i = 0; i < n; ++i)
    sum += sin(dot(p, dir) * (float)(i + 1)) * m;
  return sum * twice + scaled + varying + bumped + bump + (float)per;
}
