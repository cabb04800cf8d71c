/* ref_textures.cl: the texture functions of textures/blender/noise.cl and userfbm.cl, unchanged
 * (#include), compiled by clang-15 -O3 as native code over arrays of points (ref.c calls these
 * entry points). Each entry point has a run-time variant (the parameters from memory, so that
 * nothing folds) and a folded one (the parameters as literals, as texcc's inline mode passes
 * them). Voronoi is in ref_voronoi.cl (voronoi.cl and noise.cl both define hash.h's functions:
 * one translation unit each). */
#include "cl_compat.h"
#include "../../textures/blender/noise.cl"
#include "userfbm.cl"
#include "ref_params.h"

/* Points as x, y, z triples; outputs as r, g, b triples. */
#define REF_LOOP(EXPR)                                                                           \
  for (int i = 0; i < n; ++i) {                                                                  \
    float3 v = (float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);                             \
    float3 c = EXPR;                                                                             \
    out[3 * i] = c.x, out[3 * i + 1] = c.y, out[3 * i + 2] = c.z;                                \
  }

/* Noise 3D Color, Detail 7 (fBM: type 1, offset 0, gain 1; ridged: type 3, offset 1, gain 2). */
void refNoiseRuntime(const float *pts, float *out, int n, const RefParams *q) {
  REF_LOOP(blNoise3DColor(v, q->scale, q->detail, q->roughness, q->lacunarity, q->offset, q->gain,
                          q->distortion, q->type, q->normalize))
}

void refNoiseFolded(const float *pts, float *out, int n) {
  REF_LOOP(blNoise3DColor(v, 5.0f, 7.0f, 0.5f, 2.0f, 0.0f, 1.0f, 0.0f, 1, 1))
}

void refRidgedFolded(const float *pts, float *out, int n) {
  REF_LOOP(blNoise3DColor(v, 5.0f, 7.0f, 0.5f, 2.0f, 1.0f, 2.0f, 0.0f, 3, 1))
}

/* Wave Bands X, Sine, Distortion 1, Detail 7 (Color). */
void refWaveRuntime(const float *pts, float *out, int n, const RefParams *q) {
  REF_LOOP(blWaveColor(v, q->scale, q->distortion, q->detail, q->detailScale, q->roughness,
                       q->offset, q->type, q->direction, q->profile))
}

void refWaveFolded(const float *pts, float *out, int n) {
  REF_LOOP(blWaveColor(v, 5.0f, 1.0f, 7.0f, 1.0f, 0.5f, 0.0f, 0, 0, 0))
}

void refFbmRuntime(const float *pts, float *out, int n, const RefParams *q) {
  REF_LOOP(userFbm(v, q->scale, q->octaves, q->lacunarity, q->gain))
}

void refFbmFolded(const float *pts, float *out, int n) {
  REF_LOOP(userFbm(v, 4.0f, 8, 2.0f, 0.5f))
}
