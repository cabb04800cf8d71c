/* ref_voronoi.cl: textures/blender/voronoi.cl's Voronoi 3D F1 Distance (Euclidean, Randomness
 * 1), unchanged (#include), over arrays of points for ref.c, with run-time and folded
 * parameters (ref_textures.cl describes the two). The output is texrender's colour of a float
 * node: (distance, 0, 0). */
#include "cl_compat.h"
#include "../../textures/blender/voronoi.cl"
#include "ref_params.h"

void refVoronoiRuntime(const float *pts, float *out, int n, const RefParams *q) {
  for (int i = 0; i < n; ++i) {
    float3 v = (float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
    out[3 * i] = blVoronoi3DDistance(v, q->scale, q->detail, q->roughness, q->lacunarity,
                                     q->smoothness, q->exponent, q->randomness, q->type,
                                     q->direction, q->normalize);
    out[3 * i + 1] = out[3 * i + 2] = 0.0f;
  }
}

void refVoronoiFolded(const float *pts, float *out, int n) {
  for (int i = 0; i < n; ++i) {
    float3 v = (float3)(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
    out[3 * i] = blVoronoi3DDistance(v, 5.0f, 0.0f, 0.5f, 2.0f, 1.0f, 0.5f, 1.0f, 0, 0, 0);
    out[3 * i + 1] = out[3 * i + 2] = 0.0f;
  }
}
