/* userfbm.cl: a user's own texture for bench/texture_speed.py (issue 39): an fBM of 3D value
 * noise whose lattice values come from a PCG hash (Jarzynski and Olano's pcg3d), the kind of
 * function a user writes by hand. The same code runs in texrender (texcc) and, through
 * cl_compat.h, as C in bench/cpp_reference/ref.c.
 *
 *   float3 userFbm(float3 p, float scale, int octaves, float lacunarity, float gain)
 *
 *   | name       | type   | default | meaning                                  |
 *   |------------|--------|---------|------------------------------------------|
 *   | p          | float3 | -       | lookup point                             |
 *   | scale      | float  | 4.0     | lattice cells per unit of p              |
 *   | octaves    | int    | 8       | octaves summed                           |
 *   | lacunarity | float  | 2.0     | frequency factor per octave              |
 *   | gain       | float  | 0.5     | amplitude factor per octave              |
 */

/* pcg3d: three 32-bit words in, three hashed words out. */
uint3 ufPcg3d(uint3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

/* The lattice value at integer point c: three channels in [0, 1). */
float3 ufLattice(int3 c) {
  uint3 h = ufPcg3d(as_uint3(c));
  return convert_float3(h >> 8u) * (1.0f / 16777216.0f);
}

float ufSmooth(float t) { return t * t * (3.0f - 2.0f * t); }

/* Trilinear value noise of the 8 lattice corners around p, smoothstep-blended. */
float3 ufValueNoise(float3 p) {
  float3 f = floor(p);
  int3 c = convert_int3(f);
  float3 t = p - f;
  float u = ufSmooth(t.x), v = ufSmooth(t.y), w = ufSmooth(t.z);
  float3 a = mix(mix(ufLattice(c), ufLattice(c + (int3)(1, 0, 0)), u),
                 mix(ufLattice(c + (int3)(0, 1, 0)), ufLattice(c + (int3)(1, 1, 0)), u), v);
  float3 b = mix(mix(ufLattice(c + (int3)(0, 0, 1)), ufLattice(c + (int3)(1, 0, 1)), u),
                 mix(ufLattice(c + (int3)(0, 1, 1)), ufLattice(c + (int3)(1, 1, 1)), u), v);
  return mix(a, b, w);
}

float3 userFbm(float3 p, float scale, int octaves, float lacunarity, float gain) {
  float3 sum = (float3)(0.0f);
  float amp = 0.5f, freq = scale, norm = 0.0f;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * ufValueNoise(p * freq);
    norm += amp;
    amp *= gain;
    freq *= lacunarity;
  }
  return sum / norm;
}
