/* accumulate.cl: adds the radiance of a pass's paths to the per-pixel sums and sums of squares
 * (for the variance estimate); the paths of pixel p are p*sppPerPass .. p*sppPerPass +
 * sppPerPass - 1. Non-finite samples are dropped and counted (counters[RT_COUNT_NONFINITE],
 * stats.json "nonFiniteSamples"). */
#include "rt_types.h"

__kernel void accumulate(__global const RtPath *paths, int numPixels, int sppPerPass,
                         __global float4 *sums, __global float4 *sumsSquared,
                         __global uint *counters) {
  int p = get_global_id(0);
  if (p >= numPixels)
    return;
  float3 s = (float3)(0.0f), s2 = (float3)(0.0f);
  uint dropped = 0;
  for (int k = 0; k < sppPerPass; ++k) {
    float3 r = paths[p * sppPerPass + k].radiance.xyz;
    /* A NaN or infinite sample (a numerical accident) must not poison the pixel. */
    if (isfinite(r.x) && isfinite(r.y) && isfinite(r.z))
    {
      s += r;
      s2 += r * r;
    } else {
      ++dropped;
    }
  }
  if (dropped)
    atomic_add(&counters[RT_COUNT_NONFINITE], dropped);
  sums[p].xyz += s;
  sumsSquared[p].xyz += s2;
}
