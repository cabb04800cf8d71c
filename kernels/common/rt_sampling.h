/* rt_sampling.h: random numbers (PCG; Owen-scrambled Sobol for the first dimensions of each
 * vertex, docs/sampling.md), sample warps and orthonormal frames for the fixed
 * kernels. OpenCL C 1.2. */
#ifndef RT_SAMPLING_H
#define RT_SAMPLING_H

#define RT_PI 3.14159265358979323846f
#define RT_INV_PI 0.31830988618379067154f

/* A 32-bit hash (PCG output permutation): seeds independent streams. */
static inline uint rt_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

static inline uint rt_seed(uint a, uint b, uint c) {
  return rt_hash(a ^ rt_hash(b ^ rt_hash(c)));
}

/* Next uniform float in [0, 1). */
static inline float rt_rand(uint *state) {
  uint s = *state;
  *state = s * 747796405u + 2891336453u;
  uint word = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
  word = (word >> 22u) ^ word;
  return (float)(word >> 8) * (1.0f / 16777216.0f);
}

/* The low-discrepancy sampler: the first dimensions of a path vertex (the pixel position, the
 * light choice and the point on the light, the BSDF sample) come from the first two dimensions
 * of the Sobol sequence with Owen scrambling by hashing (Burley 2020, "Practical Hash-based
 * Owen Scrambling"). A pattern is one or two dimensions used together (a 2D point or a 1D
 * choice); its sample `index` is the pixel's sample index after a nested uniform scramble (a
 * shuffle of the order that keeps the power-of-two prefixes stratified), and each coordinate
 * is Owen-scrambled with its own seed. Every pattern (the camera's, each vertex's light choice,
 * light point and BSDF sample) has its own seed derived from the pixel's key (the full-film
 * pixel index and --seed): patterns and pixels are as decorrelated as independent random
 * numbers, while the samples of one pixel within a pattern are stratified. Dimension 0 is the
 * van der Corput sequence (bit reversal); dimension 1 is Sobol's second (generator matrix:
 * Pascal's triangle mod 2, computed as a superset XOR over the index's bit positions). */

/* Bit i of x goes to bit 31 - i. */
static inline uint rt_reverse_bits(uint x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

/* Owen scrambling of a 32-bit fixed-point value by hashing: a bijection in which each bit is
 * flipped by a function of the seed and of the bits above it only (a Laine-Karras style
 * permutation on the reversed bits, with Vegdahl's constants). */
static inline uint rt_owen(uint x, uint seed) {
  x = rt_reverse_bits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return rt_reverse_bits(x);
}

/* Sobol's dimension 1 of point `index` as 32-bit fixed point: output bit 31 - j is the XOR of
 * the index bits k with C(k, j) odd, i.e. k a superset of j's bits (Lucas). */
static inline uint rt_sobol1(uint index) {
  uint y = index;
  y ^= (y >> 1) & 0x55555555u;
  y ^= (y >> 2) & 0x33333333u;
  y ^= (y >> 4) & 0x0f0f0f0fu;
  y ^= (y >> 8) & 0x00ff00ffu;
  y ^= (y >> 16) & 0x0000ffffu;
  return rt_reverse_bits(y);
}

static inline float rt_unit(uint x) { return (float)(x >> 8) * (1.0f / 16777216.0f); }

/* The seed of pattern `pattern` of a pixel whose key is `key` (rt_pixel_key). */
static inline uint rt_pattern_seed(uint key, uint pattern) {
  return rt_hash(key ^ rt_hash(pattern));
}

/* Sample `index` of a 2D pattern, in [0, 1)^2. */
static inline float2 rt_sobol2(uint index, uint seed) {
  uint i = rt_owen(index, seed);
  return (float2)(rt_unit(rt_owen(rt_reverse_bits(i), rt_hash(seed ^ 0x68bc21ebu))),
                  rt_unit(rt_owen(rt_sobol1(i), rt_hash(seed ^ 0x02e5be93u))));
}

/* Sample `index` of a 1D pattern, in [0, 1). */
static inline float rt_sobol1d(uint index, uint seed) {
  return rt_unit(rt_owen(rt_reverse_bits(rt_owen(index, seed)), rt_hash(seed ^ 0x68bc21ebu)));
}

/* 8 lanes of the integer maths above (lane k: the same bits as the scalar function of lane k);
 * PoCL vectorizes neither a scalar loop over 8 points nor across work-items, but compiles
 * uint8 / float8 maths to SIMD instructions (a hit's AO rays, ao.cl). */
static inline uint8 rt_reverse_bits8(uint8 x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

static inline uint8 rt_sobol1_8(uint8 index) {
  uint8 y = index;
  y ^= (y >> 1) & 0x55555555u;
  y ^= (y >> 2) & 0x33333333u;
  y ^= (y >> 4) & 0x0f0f0f0fu;
  y ^= (y >> 8) & 0x00ff00ffu;
  y ^= (y >> 16) & 0x0000ffffu;
  return rt_reverse_bits8(y);
}

static inline uint8 rt_hash8(uint8 v) {
  uint8 state = v * 747796405u + 2891336453u;
  uint8 word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

static inline float8 rt_unit8(uint8 x) { return convert_float8(x >> 8) * (1.0f / 16777216.0f); }

/* A full Owen scramble of 32-bit fixed-point values v (8 lanes) whose top `levels` bits tell
 * them apart (the first 2^levels points of a Sobol dimension): the top bits by the scramble's
 * tree, one random flip per node (level k, the bits above k), each flip its own bit of a hash
 * of seed; every bit below them random per point (a hash of seed and the point's top bits).
 * rt_owen's hashed permutation (Laine-Karras with Burley's constants) is not distributed so:
 * on 8 points its flips are correlated, and an estimate from them (the 8 AO rays) spreads up
 * to 25% less or 10% more than from Owen-scrambled points, by the integrand's orientation
 * (issue 22: Cycles' tabulated Sobol points are Owen-scrambled; bench/cycles.md, session 9). */
static inline uint8 rt_owen_top8(uint8 v, uint levels, uint seed) {
  uint h = rt_hash(seed);
  uint8 out = (uint8)0u, node = (uint8)1u; /* node: the tree node's heap index, 1 = root */
  for (uint k = 0; k < levels; ++k) {
    uint8 bit = (v >> (31u - k)) & 1u;
    uint8 flips = levels <= 5u ? (uint8)h : rt_hash8(h + (node >> 5u) * 0x9e3779b9u);
    out |= (bit ^ ((flips >> (node & 31u)) & 1u)) << (31u - k);
    node = (node << 1u) | bit;
  }
  return out | (rt_hash8(node ^ rt_hash(seed ^ 0x5bd1e995u)) >> levels);
}

/* Points index.s0 .. index.s7 of a 2D pattern of 2^levels points (indices below 2^levels),
 * in [0, 1)^2: Sobol's first two dimensions, fully Owen-scrambled (rt_owen_top8), each
 * dimension with its own seed. Any 2^m aligned points of them are stratified as a (0, m, 2)
 * net; a hit's AO rays (ao.cl), distributed as the AO node's rays of Cycles' default pattern
 * (aligned blocks of its tabulated, stochastically Owen-scrambled Sobol sequences). */
static inline void rt_owen_net2_8(uint8 index, uint levels, uint seed, float8 *u1, float8 *u2) {
  *u1 = rt_unit8(rt_owen_top8(rt_reverse_bits8(index), levels, rt_hash(seed ^ 0x68bc21ebu)));
  *u2 = rt_unit8(rt_owen_top8(rt_sobol1_8(index), levels, rt_hash(seed ^ 0x02e5be93u)));
}

/* Bench-only: with RT_SAMPLER_PCG defined, every pattern is independent PCG numbers from the
 * path's stream instead (the sampler before issue 26; bench/sampling.py --sampler pcg). */
#ifdef RT_SAMPLER_PCG
#define RT_SAMPLE2(rng, index, seed) rt_rand2(rng)
#define RT_SAMPLE1(rng, index, seed) rt_rand(rng)
#else
#define RT_SAMPLE2(rng, index, seed) rt_sobol2(index, seed)
#define RT_SAMPLE1(rng, index, seed) rt_sobol1d(index, seed)
#endif

static inline float2 rt_rand2(uint *rng) {
  float a = rt_rand(rng);
  return (float2)(a, rt_rand(rng));
}

/* The key of a full-film pixel under --seed: the same whatever the region or pass. */
static inline uint rt_pixel_key(uint pixel, uint seed) {
  return rt_hash(pixel ^ rt_hash(seed ^ 0x2c1b3c6du));
}

/* Patterns of a path: the camera's pixel position; at each vertex (depth = segments traced so
 * far) the light choice, the point on the light, the BSDF sample and the choice of a leaf in
 * the material's blend tree. */
#define RT_PATTERN_CAMERA 0u
#define RT_PATTERN_LIGHT_CHOICE(depth) (4u * (uint)(depth) + 1u)
#define RT_PATTERN_LIGHT(depth) (4u * (uint)(depth) + 2u)
#define RT_PATTERN_BSDF(depth) (4u * (uint)(depth) + 3u)
#define RT_PATTERN_BLEND(depth) (4u * (uint)(depth) + 4u)

/* Builds tangents t, b so that (t, b, n) is orthonormal (Duff et al. 2017). */
static inline void rt_frame(float3 n, float3 *t, float3 *b) {
  float sign = copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

static inline float3 rt_to_world(float3 v, float3 n) {
  float3 t, b;
  rt_frame(n, &t, &b);
  return v.x * t + v.y * b + v.z * n;
}

/* Cosine-weighted hemisphere around +z; pdf = z / pi. */
static inline float3 rt_sample_cosine(float u1, float u2) {
  float r = sqrt(u1);
  float phi = 2.0f * RT_PI * u2;
  return (float3)(r * cos(phi), r * sin(phi), sqrt(fmax(0.0f, 1.0f - u1)));
}

/* 8 directions at once (lane k from (u1.sk, u2.sk); a hit's AO rays, ao.cl's ao_dirs8), each
 * cosine-weighted around +z, pdf = z / pi, through the concentric map of the square
 * onto the unit disk (Shirley and Chiu 1997), lifted onto the hemisphere: the warp of Cycles'
 * Ambient Occlusion node. Same distribution as rt_sample_cosine, but a stratified set of (u1, u2)
 * becomes a differently stratified set of directions (square cells stay compact on the disk;
 * rt_sample_cosine's become rings and wedges), so an estimate from a few directions has another
 * spread (issue 22). */
static inline void rt_sample_cosine_concentric8(float8 u1, float8 u2, float8 *x, float8 *y,
                                                float8 *z) {
  /* The map's branches are selects (the lanes' divisions by zero are not selected). */
  float8 a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  int8 first = a * a > b * b, second = !first & (b != 0.0f);
  float8 r = select(select((float8)0.0f, b, second), a, first);
  float8 phi = select(select((float8)0.0f, 0.5f * RT_PI - 0.25f * RT_PI * (a / b), second),
                      0.25f * RT_PI * (b / a), first);
  float8 c, s = sincos(phi, &c); /* the bits of cos and sin on PoCL, at half the cost */
  *x = r * c, *y = r * s;
  *z = sqrt(fmax(0.0f, 1.0f - *x * *x - *y * *y));
}

/* The tangent pair Cycles builds around a unit normal n (its make_orthonormals): t along
 * (1, 1, 1) x n ((-1, 1, 1) x n when n's three components are equal), b = n x t. */
static inline void rt_frame_cycles(float3 n, float3 *t, float3 *b) {
  *t = normalize((n.x != n.y || n.x != n.z) ? (float3)(n.z - n.y, n.x - n.z, n.y - n.x)
                                            : (float3)(n.z - n.y, n.x + n.z, -n.y - n.x));
  *b = cross(n, *t);
}

/* Uniform sphere; pdf = 1 / (4 pi). */
static inline float3 rt_sample_sphere(float u1, float u2) {
  float z = 1.0f - 2.0f * u1;
  float r = sqrt(fmax(0.0f, 1.0f - z * z));
  float phi = 2.0f * RT_PI * u2;
  return (float3)(r * cos(phi), r * sin(phi), z);
}

/* Uniform cone of directions around +z with cos(half angle) = cosMax; pdf = 1/(2pi(1-cosMax)). */
static inline float3 rt_sample_cone(float u1, float u2, float cosMax) {
  float z = 1.0f - u1 * (1.0f - cosMax);
  float r = sqrt(fmax(0.0f, 1.0f - z * z));
  float phi = 2.0f * RT_PI * u2;
  return (float3)(r * cos(phi), r * sin(phi), z);
}

/* Uniform point on a triangle: barycentrics (b1, b2). */
static inline float2 rt_sample_triangle(float u1, float u2) {
  float s = sqrt(u1);
  return (float2)(1.0f - s, u2 * s);
}

static inline float rt_max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }

/* The power heuristic (as Mitsuba 3's path tracer). */
static inline float rt_mis(float a, float b) {
  float a2 = a * a;
  return a2 > 0.0f ? a2 / (a2 + b * b) : 0.0f;
}

#endif
