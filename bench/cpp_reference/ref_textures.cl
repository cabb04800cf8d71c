/* ref_textures.cl: the texture functions of textures/blender/noise.cl and userfbm.cl, unchanged
 * (#include), compiled by clang-15 -O3 as native code over arrays of points (ref.c calls these
 * entry points). Each entry point has a run-time variant (the parameters from memory, so that
 * nothing folds) and a folded one (the parameters as literals, as texcc's inline mode passes
 * them). */
#include "cl_compat.h"
#include "../../textures/blender/noise.cl"
#include "userfbm.cl"

typedef struct RefParams {
  float scale, detail, roughness, lacunarity, offset, gain, distortion;
  int type, normalize, octaves;
} RefParams;

/* Points as x, y, z triples; outputs as r, g, b triples. */
void refNoiseRuntime(const float *pts, float *out, int n, const RefParams *q) {
  for (int i = 0; i < n; ++i) {
    float3 c = blNoise3DColor((float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]), q->scale,
                              q->detail, q->roughness, q->lacunarity, q->offset, q->gain,
                              q->distortion, q->type, q->normalize);
    out[3 * i] = c.x, out[3 * i + 1] = c.y, out[3 * i + 2] = c.z;
  }
}

void refNoiseFolded(const float *pts, float *out, int n) {
  for (int i = 0; i < n; ++i) {
    float3 c = blNoise3DColor((float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]), 5.0f, 7.0f,
                              0.5f, 2.0f, 0.0f, 1.0f, 0.0f, 1, 1);
    out[3 * i] = c.x, out[3 * i + 1] = c.y, out[3 * i + 2] = c.z;
  }
}

void refFbmRuntime(const float *pts, float *out, int n, const RefParams *q) {
  for (int i = 0; i < n; ++i) {
    float3 c = userFbm((float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]), q->scale,
                       q->octaves, q->lacunarity, q->gain);
    out[3 * i] = c.x, out[3 * i + 1] = c.y, out[3 * i + 2] = c.z;
  }
}

void refFbmFolded(const float *pts, float *out, int n) {
  for (int i = 0; i < n; ++i) {
    float3 c = userFbm((float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]), 4.0f, 8, 2.0f, 0.5f);
    out[3 * i] = c.x, out[3 * i + 1] = c.y, out[3 * i + 2] = c.z;
  }
}
