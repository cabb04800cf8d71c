/* rt_sampling.h: random numbers (PCG), sample warps and orthonormal frames for the fixed
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
