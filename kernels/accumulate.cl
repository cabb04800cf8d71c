/* accumulate.cl: adds the radiance of a pass's paths to the per-pixel sums and sums of squares
 * (for the variance estimate); the paths of pixel p are p*sppPerPass .. p*sppPerPass +
 * sppPerPass - 1.
 * - A sample with a NaN or infinite component (shade.cl makes a path's sample NaN when a
 *   texture value, a BSDF weight or a light sample was non-finite) is dropped and counted
 *   (counters[RT_COUNT_NONFINITE], stats.json "nonFiniteSamples"): it adds nothing, the pixel's
 *   mean still divides by the full sample count.
 * - Finite samples are summed with saturation: a sum or sum of squares that would overflow
 *   stays at +-FLT_MAX (a sample of 1e20 has a square of 1e40, more than a float holds), and
 *   the samples that saturated a sum are counted (counters[RT_COUNT_SATURATED], stats.json
 *   "saturatedSamples"). The sums never hold Inf or NaN. */
#include "rt_types.h"

/* a + b, kept within the finite floats (a and b finite). */
static inline float3 rt_add_saturating(float3 a, float3 b, int *saturated) {
  float3 s = a + b;
  float3 c = clamp(s, -FLT_MAX, FLT_MAX);
  if (any(isinf(s)))
    *saturated = 1;
  return c;
}

__kernel void accumulate(__global const RtPath *paths, int numPixels, int sppPerPass,
                         __global float4 *sums, __global float4 *sumsSquared,
                         __global uint *counters) {
  int p = get_global_id(0);
  if (p >= numPixels)
    return;
  /* One running sum per pixel, sample after sample: the same result whatever the passes. */
  float3 s = sums[p].xyz, s2 = sumsSquared[p].xyz;
  uint dropped = 0, saturatedSamples = 0;
  for (int k = 0; k < sppPerPass; ++k) {
    float3 r = paths[p * sppPerPass + k].radiance.xyz;
    /* A NaN or infinite sample (a numerical accident) must not poison the pixel. */
    if (isfinite(r.x) && isfinite(r.y) && isfinite(r.z)) {
      int saturated = 0;
      s = rt_add_saturating(s, r, &saturated);
      s2 = rt_add_saturating(s2, r * r, &saturated); /* r * r may be +Inf: clamped */
      saturatedSamples += saturated;
    } else {
      ++dropped;
    }
  }
  if (dropped)
    atomic_add(&counters[RT_COUNT_NONFINITE], dropped);
  if (saturatedSamples)
    atomic_add(&counters[RT_COUNT_SATURATED], saturatedSamples);
  sums[p].xyz = s;
  sumsSquared[p].xyz = s2;
}
