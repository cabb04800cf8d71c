/* raygen.cl: one camera ray per path. Path i of a pass samples pixel i / sppPerPass of the
 * region (regionX, regionY, regionWidth wide, inside the width x height film) with the sample
 * index passStart + i % sppPerPass; the pixel position is uniform in the pixel (box filter, as
 * Mitsuba's `box` rfilter), from the camera pattern of the Owen-scrambled Sobol sampler
 * (rt_sampling.h). The random stream, the sampler's pixel key and RtPath.pixel use the
 * full-film pixel index, so that a region renders exactly the pixels of a whole render
 * (texrender --region). rowStep > 1 renders every rowStep-th row of the region from its
 * first (a lane of a frame: texrender's lanes, Lanes.h); regionY + r * rowStep is row r's film
 * row. The path keeps its sample index in origin.w and the pixel key in
 * throughput.w (as uint bits) for the sampler's later dimensions (shade.cl). */
#include "rt_sampling.h"
#include "rt_types.h"

__kernel void raygen(__global RtPath *paths, __global int *active, __global const RtCamera *camera,
                     int width, int height, int sppPerPass, int passStart, uint seed,
                     int numPaths, int regionX, int regionY, int regionWidth, int rowStep) {
  int i = get_global_id(0);
  if (i >= numPaths)
    return;
  int inRegion = i / sppPerPass;
  int x = regionX + inRegion % regionWidth, y = regionY + (inRegion / regionWidth) * rowStep;
  int pixel = y * width + x;
  int sample = passStart + i % sppPerPass;
  uint rng = rt_seed((uint)pixel, (uint)sample, seed);
  uint key = rt_pixel_key((uint)pixel, seed);
  float2 j = RT_SAMPLE2(&rng, (uint)sample, rt_pattern_seed(key, RT_PATTERN_CAMERA));
  float px = (float)x + j.x;
  float py = (float)y + j.y;
  float sx = 2.0f * px / (float)width - 1.0f;
  float sy = 1.0f - 2.0f * py / (float)height;
  RtCamera c = *camera;
  float3 d = normalize(c.forward.xyz + sx * c.right.xyz + sy * c.up.xyz);
  RtPath p;
  p.origin = (float4)(c.position.xyz, as_float((uint)sample));
  p.dir = (float4)(d, 0.0f);
  p.throughput = (float4)(1.0f, 1.0f, 1.0f, as_float(key));
  p.radiance = (float4)(0.0f);
  p.pixel = (uint)pixel;
  p.rng = rng;
  p.depth = 1;
  p.flags = RT_PATH_ALIVE | RT_PATH_SPECULAR;
  paths[i] = p;
  active[i] = i;
}
