/* ref.c: the C reference of bench/texture_speed.py and bench/per_node_cycles.py (issue 39).
 * Times the texture functions of ref_textures.cl and ref_voronoi.cl (textures/blender/noise.cl's
 * blNoise3DColor fBM and ridged and blWaveColor, voronoi.cl's blVoronoi3DDistance, userfbm.cl's
 * userFbm: the same source texrender runs, compiled by clang-15 -O3 as native code) over an
 * array of points, one thread, with the parameters as run-time values and folded to literals.
 *
 * usage: ref [--points N] [--rounds R] [--dump-points FILE] [--dump-values FILE]
 *
 * Points: N (default 4096) uniform in [-1, 1]^3 (a fixed LCG). Each round runs every variant
 * once over all points, in an order that rotates with the round; prints one JSON object with
 * each variant's ns per sample per round, the median and the minimum. --dump-points writes the
 * points (x y z per line, texcc-eval --points), --dump-values the run-time variants' outputs
 * (%.9g; per line noise r g b, fbm r g b, ridged r g b, voronoi d 0 0, wave r g b) for the
 * comparison with texcc-eval. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ref_params.h"

void refNoiseRuntime(const float *pts, float *out, int n, const RefParams *q);
void refNoiseFolded(const float *pts, float *out, int n);
void refRidgedFolded(const float *pts, float *out, int n);
void refWaveRuntime(const float *pts, float *out, int n, const RefParams *q);
void refWaveFolded(const float *pts, float *out, int n);
void refVoronoiRuntime(const float *pts, float *out, int n, const RefParams *q);
void refVoronoiFolded(const float *pts, float *out, int n);
void refFbmRuntime(const float *pts, float *out, int n, const RefParams *q);
void refFbmFolded(const float *pts, float *out, int n);

/* cl_compat.h's get_global_id reads it; nothing here calls it. */
unsigned long clcGlobalId(void) { return 0; }

enum {
  NOISE_RT, NOISE_FOLDED, FBM_RT, FBM_FOLDED, RIDGED_RT, RIDGED_FOLDED, VORONOI_RT,
  VORONOI_FOLDED, WAVE_RT, WAVE_FOLDED, VARIANTS
};
static const char *const Names[VARIANTS] = {
    "noise3d-color-detail7/runtime", "noise3d-color-detail7/folded", "userfbm/runtime",
    "userfbm/folded", "noise3d-ridged-detail7/runtime", "noise3d-ridged-detail7/folded",
    "voronoi3d-f1/runtime", "voronoi3d-f1/folded", "wave-bands-x-distortion1-detail7/runtime",
    "wave-bands-x-distortion1-detail7/folded"};
/* --dump-values' columns: these run-time variants, three columns each. */
static const int Dumped[] = {NOISE_RT, FBM_RT, RIDGED_RT, VORONOI_RT, WAVE_RT};
enum { DUMPED = sizeof Dumped / sizeof Dumped[0] };

/* The thread's CPU time: on the shared machine a preempted round would count the other
 * processes' time by the wall clock. */
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* Run-time parameters: read through a volatile pointer so that the compiler cannot see them;
 * each variant then sets its own from memory too (the volatile copy keeps them opaque). */
static RefParams params(void) {
  static volatile RefParams v = {5.0f, 7.0f, 0.5f, 2.0f, 0.0f, 1.0f, 0.0f, 1, 1, 0,
                                 1.0f, 1.0f, 0.5f, 1.0f, 0, 0};
  RefParams q;
  memcpy(&q, (const void *)&v, sizeof q);
  return q;
}

static void run(int k, const float *pts, float *out, int n) {
  RefParams q = params();
  switch (k) {
  case NOISE_RT: refNoiseRuntime(pts, out, n, &q); break;
  case NOISE_FOLDED: refNoiseFolded(pts, out, n); break;
  case FBM_RT:
    q.scale = 4.0f, q.octaves = 8, q.lacunarity = 2.0f, q.gain = 0.5f;
    refFbmRuntime(pts, out, n, &q);
    break;
  case FBM_FOLDED: refFbmFolded(pts, out, n); break;
  case RIDGED_RT:
    q.type = 3, q.offset = 1.0f, q.gain = 2.0f;
    refNoiseRuntime(pts, out, n, &q);
    break;
  case RIDGED_FOLDED: refRidgedFolded(pts, out, n); break;
  case VORONOI_RT:
    /* detail 0, roughness 0.5, lacunarity 2, smoothness 1, exponent 0.5, randomness 1, F1
     * (type 0), Euclidean (direction 0), not normalized */
    q.detail = 0.0f, q.smoothness = 1.0f, q.exponent = 0.5f, q.randomness = 1.0f, q.type = 0,
    q.direction = 0, q.normalize = 0;
    refVoronoiRuntime(pts, out, n, &q);
    break;
  case VORONOI_FOLDED: refVoronoiFolded(pts, out, n); break;
  case WAVE_RT:
    /* distortion 1, detail 7, detail scale 1, detail roughness 0.5 (roughness), phase offset 0
     * (offset), Bands (type 0), X (direction 0), Sine (profile 0) */
    q.distortion = 1.0f, q.detailScale = 1.0f, q.offset = 0.0f, q.type = 0, q.direction = 0,
    q.profile = 0;
    refWaveRuntime(pts, out, n, &q);
    break;
  default: refWaveFolded(pts, out, n); break;
  }
}

int main(int argc, char **argv) {
  int n = 4096, rounds = 21;
  const char *dumpPoints = NULL, *dumpValues = NULL;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--points") && i + 1 < argc) n = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--dump-points") && i + 1 < argc) dumpPoints = argv[++i];
    else if (!strcmp(argv[i], "--dump-values") && i + 1 < argc) dumpValues = argv[++i];
    else {
      fprintf(stderr, "ref: error: unknown argument '%s'\n", argv[i]);
      return 1;
    }
  }
  if (n <= 0 || rounds <= 0) {
    fprintf(stderr, "ref: error: --points and --rounds must be positive\n");
    return 1;
  }
  float *pts = malloc(sizeof(float) * 3 * n), *out = malloc(sizeof(float) * 3 * n);
  double *t = malloc(sizeof(double) * rounds * VARIANTS);
  unsigned s = 12345u;
  for (int i = 0; i < 3 * n; ++i) {
    s = s * 1664525u + 1013904223u;
    pts[i] = (float)(s >> 8) * (2.0f / 16777216.0f) - 1.0f;
  }
  if (dumpPoints) {
    FILE *f = fopen(dumpPoints, "w");
    if (!f) { fprintf(stderr, "ref: error: cannot write %s\n", dumpPoints); return 1; }
    for (int i = 0; i < n; ++i) fprintf(f, "%.9g %.9g %.9g\n", pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
    fclose(f);
  }
  if (dumpValues) {
    FILE *f = fopen(dumpValues, "w");
    if (!f) { fprintf(stderr, "ref: error: cannot write %s\n", dumpValues); return 1; }
    float *all = malloc(sizeof(float) * 3 * n * DUMPED);
    for (int d = 0; d < DUMPED; ++d) run(Dumped[d], pts, all + 3 * n * d, n);
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < DUMPED; ++d) {
        const float *v = all + 3 * n * d + 3 * i;
        fprintf(f, "%.9g %.9g %.9g%s", v[0], v[1], v[2], d + 1 < DUMPED ? " " : "\n");
      }
    free(all);
    fclose(f);
  }
  for (int k = 0; k < VARIANTS; ++k) run(k, pts, out, n); /* warm up */
  for (int r = 0; r < rounds; ++r)
    for (int j = 0; j < VARIANTS; ++j) {
      int k = (j + r) % VARIANTS;
      double t0 = now();
      run(k, pts, out, n);
      t[k * rounds + r] = (now() - t0) * 1e9 / n;
    }
  printf("{\"points\": %d, \"rounds\": %d, \"variants\": {", n, rounds);
  for (int k = 0; k < VARIANTS; ++k) {
    double *v = t + k * rounds, *sorted = malloc(sizeof(double) * rounds);
    memcpy(sorted, v, sizeof(double) * rounds);
    qsort(sorted, rounds, sizeof(double), cmp);
    printf("%s\"%s\": {\"medianNsPerSample\": %.2f, \"minNsPerSample\": %.2f, \"nsPerSample\": [",
           k ? ", " : "", Names[k], sorted[rounds / 2], sorted[0]);
    for (int r = 0; r < rounds; ++r) printf("%s%.2f", r ? ", " : "", v[r]);
    printf("]}");
    free(sorted);
  }
  printf("}}\n");
  free(pts), free(out), free(t);
  return 0;
}
