/* tex.cl: textures for the principled tests (testsuite/runtime/principled-*.test). */

/* Stripes of colors a and b across p.x + p.y. */
float3 stripes(float3 p, float3 a, float3 b, float freq) {
  float t = 0.5f + 0.5f * sin(freq * (p.x + p.y));
  return mix(a, b, t);
}

/* A roughness between lo and hi varying with p.z. */
float roughAlong(float3 p, float lo, float hi) {
  return mix(lo, hi, 0.5f + 0.5f * cos(3.0f * p.z));
}

/* The normal n tilted by a wave along p (a hand-written bump). */
float3 wavyNormal(float3 n, float3 p, float amp, float freq) {
  return normalize(n + amp * (float3)(sin(freq * p.x), sin(freq * p.y), cos(freq * p.z)));
}

/* n * s: with s = -1 a normal below the surface, with s = 0 a zero one. */
float3 scaledNormal(float3 n, float s) { return n * s; }

/* n * sqrt(x): NaN for x < 0. */
float3 nanNormal(float3 n, float x) { return n * sqrt(x); }
