/* noise.cl: gradient (Perlin) noise and the fractals built on it.
 *
 * Improved Perlin noise (Perlin 2002): pseudo-random gradients on the integer lattice of
 * p * scale, blended with the quintic fade 6t^5 - 15t^4 + 10t^3, so the noise is C2-continuous
 * everywhere (across lattice cell borders too) and exactly 0 at every lattice point. The lattice
 * hash is an integer mix (no permutation table), so the noise does not repeat.
 *
 * Texture functions (graph "fn" names):
 *
 *   float perlin2(float2 p, float scale)          2D gradient noise, range [-1, 1]
 *   float perlin3(float3 p, float scale)          3D gradient noise, range [-1, 1]
 *                                                 (standard deviation about 0.27)
 *   float fbm3(float3 p, float scale, int octaves, float lacunarity, float gain)
 *       fractional Brownian motion: sum over octaves i of gain^i * perlin3(p * scale *
 *       lacunarity^i), divided by the sum of the weights gain^i, so the range stays [-1, 1].
 *   float turbulence3(float3 p, float scale, int octaves, float lacunarity, float gain)
 *       as fbm3 with |perlin3| per octave: range [0, 1], creased at the noise's zero set.
 *   float ridged3(float3 p, float scale, int octaves, float lacunarity, float gain)
 *       ridged multifractal (after Musgrave): per octave r = (1 - |perlin3|)^2, weighted by
 *       the previous octave's r (ridges grow detail, valleys stay smooth), normalised by the
 *       sum of the weights gain^i: range [0, 1], 1 on the ridges.
 *
 * Parameters:
 *
 *   | name       | type   | default | range    | meaning                                      |
 *   |------------|--------|---------|----------|----------------------------------------------|
 *   | p          | float2/3 | -     | any      | lookup point, usually {"attr": "ObjectPos"}  |
 *   | scale      | float  | 1.0     | > 0      | lattice cells per unit of p (feature size 1/scale) |
 *   | octaves    | int    | 5       | 1..16    | number of octaves (clamped to 1..16)         |
 *   | lacunarity | float  | 2.0     | > 1      | frequency multiplier from one octave to the next |
 *   | gain       | float  | 0.5     | 0..1     | amplitude multiplier from one octave to the next |
 *
 * (OpenCL C has no default arguments: a graph gives every argument; "default" is the value
 * the examples start from.)
 */

/* A 32-bit integer finaliser (lowbias32): every input bit affects every output bit. */
uint hashU32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint hashLattice(int x, int y, int z) {
  return hashU32((uint)x + hashU32((uint)y + hashU32((uint)z)));
}

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float lerpf(float a, float b, float t) { return a + (b - a) * t; }

/* Dot product of the offset (x, y, z) with one of Perlin's 12 edge gradients, picked by h. */
float gradDot3(uint h, float x, float y, float z) {
  int k = (int)(h & 15U);
  float u = k < 8 ? x : y;
  float v = k < 4 ? y : ((k == 12 || k == 14) ? x : z);
  return ((k & 1) ? -u : u) + ((k & 2) ? -v : v);
}

/* Dot product of (x, y) with one of 8 unit gradients (axes and diagonals), picked by h. */
float gradDot2(uint h, float x, float y) {
  int k = (int)(h & 7U);
  float d = 0.70710678f;
  if (k < 4)
    return (k & 1 ? -1.0f : 1.0f) * (k < 2 ? x : y);
  return (k & 1 ? -d : d) * x + (k & 2 ? -d : d) * y;
}

float perlinAt3(float x, float y, float z) {
  float fx = floor(x), fy = floor(y), fz = floor(z);
  int ix = (int)fx, iy = (int)fy, iz = (int)fz;
  x -= fx;
  y -= fy;
  z -= fz;
  float u = fade(x), v = fade(y), w = fade(z);
  float n000 = gradDot3(hashLattice(ix, iy, iz), x, y, z);
  float n100 = gradDot3(hashLattice(ix + 1, iy, iz), x - 1.0f, y, z);
  float n010 = gradDot3(hashLattice(ix, iy + 1, iz), x, y - 1.0f, z);
  float n110 = gradDot3(hashLattice(ix + 1, iy + 1, iz), x - 1.0f, y - 1.0f, z);
  float n001 = gradDot3(hashLattice(ix, iy, iz + 1), x, y, z - 1.0f);
  float n101 = gradDot3(hashLattice(ix + 1, iy, iz + 1), x - 1.0f, y, z - 1.0f);
  float n011 = gradDot3(hashLattice(ix, iy + 1, iz + 1), x, y - 1.0f, z - 1.0f);
  float n111 = gradDot3(hashLattice(ix + 1, iy + 1, iz + 1), x - 1.0f, y - 1.0f, z - 1.0f);
  float y0 = lerpf(lerpf(n000, n100, u), lerpf(n010, n110, u), v);
  float y1 = lerpf(lerpf(n001, n101, u), lerpf(n011, n111, u), v);
  return lerpf(y0, y1, w);
}

float perlinAt2(float x, float y) {
  float fx = floor(x), fy = floor(y);
  int ix = (int)fx, iy = (int)fy;
  x -= fx;
  y -= fy;
  float u = fade(x), v = fade(y);
  /* The 2D lattice is the z = 0 slice of the 3D hash (its own gradient set, though). */
  float n00 = gradDot2(hashLattice(ix, iy, 0), x, y);
  float n10 = gradDot2(hashLattice(ix + 1, iy, 0), x - 1.0f, y);
  float n01 = gradDot2(hashLattice(ix, iy + 1, 0), x, y - 1.0f);
  float n11 = gradDot2(hashLattice(ix + 1, iy + 1, 0), x - 1.0f, y - 1.0f);
  /* Unit gradients reach at most sqrt(2)/2 in 2D: rescale to [-1, 1]. */
  return 1.41421356f * lerpf(lerpf(n00, n10, u), lerpf(n01, n11, u), v);
}

int clampOctaves(int octaves) {
  return octaves < 1 ? 1 : (octaves > 16 ? 16 : octaves);
}

float perlin2(float2 p, float scale) { return perlinAt2(p.x * scale, p.y * scale); }

float perlin3(float3 p, float scale) {
  return perlinAt3(p.x * scale, p.y * scale, p.z * scale);
}

/* mode 0: signed sum (fBm); mode 1: sum of |noise| (turbulence). */
float fractalSum3(float3 p, float scale, int octaves, float lacunarity, float gain, int mode) {
  int n = clampOctaves(octaves);
  float x = p.x * scale, y = p.y * scale, z = p.z * scale;
  float sum = 0.0f, amp = 1.0f, norm = 0.0f;
  for (int i = 0; i < n; ++i) {
    float v = perlinAt3(x, y, z);
    sum += amp * (mode == 1 ? fabs(v) : v);
    norm += amp;
    amp *= gain;
    /* A fixed shift per octave keeps the octaves' lattice zeros from lining up at p = 0. */
    x = x * lacunarity + 17.13f;
    y = y * lacunarity + 31.71f;
    z = z * lacunarity + 7.37f;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}

float fbm3(float3 p, float scale, int octaves, float lacunarity, float gain) {
  return fractalSum3(p, scale, octaves, lacunarity, gain, 0);
}

float turbulence3(float3 p, float scale, int octaves, float lacunarity, float gain) {
  return fractalSum3(p, scale, octaves, lacunarity, gain, 1);
}

float ridged3(float3 p, float scale, int octaves, float lacunarity, float gain) {
  int n = clampOctaves(octaves);
  float x = p.x * scale, y = p.y * scale, z = p.z * scale;
  float sum = 0.0f, amp = 1.0f, norm = 0.0f, weight = 1.0f;
  for (int i = 0; i < n; ++i) {
    float r = 1.0f - fabs(perlinAt3(x, y, z));
    r = r * r;
    sum += amp * r * weight;
    norm += amp;
    weight = r;
    amp *= gain;
    x = x * lacunarity + 17.13f;
    y = y * lacunarity + 31.71f;
    z = z * lacunarity + 7.37f;
  }
  return norm > 0.0f ? sum / norm : 0.0f;
}
