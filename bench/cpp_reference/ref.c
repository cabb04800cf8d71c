/* ref.c: the C reference of bench/texture_speed.py (issue 39). Times the texture functions of
 * ref_textures.cl (textures/blender/noise.cl's blNoise3DColor and userfbm.cl's userFbm, the
 * same source texrender runs, compiled by clang-15 -O3 as native code) over an array of points,
 * one thread, with the parameters as run-time values and folded to literals.
 *
 * usage: ref [--points N] [--rounds R] [--dump-points FILE] [--dump-values FILE]
 *
 * Points: N (default 4096) uniform in [-1, 1]^3 (a fixed LCG). Each round runs every variant
 * once over all points, in an order that rotates with the round; prints one JSON object with
 * each variant's ns per sample per round, the median and the minimum. --dump-points writes the
 * points (x y z per line, texcc-eval --points), --dump-values the run-time variants' outputs
 * (noise r g b, fbm r g b per line, %.9g) for the comparison with texcc-eval. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct RefParams {
  float scale, detail, roughness, lacunarity, offset, gain, distortion;
  int type, normalize, octaves;
} RefParams;

void refNoiseRuntime(const float *pts, float *out, int n, const RefParams *q);
void refNoiseFolded(const float *pts, float *out, int n);
void refFbmRuntime(const float *pts, float *out, int n, const RefParams *q);
void refFbmFolded(const float *pts, float *out, int n);

/* cl_compat.h's get_global_id reads it; nothing here calls it. */
unsigned long clcGlobalId(void) { return 0; }

enum { NOISE_RT, NOISE_FOLDED, FBM_RT, FBM_FOLDED, VARIANTS };
static const char *const Names[VARIANTS] = {"noise3d-color-detail7/runtime",
                                            "noise3d-color-detail7/folded", "userfbm/runtime",
                                            "userfbm/folded"};

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* Run-time parameters: read through a volatile pointer so that the compiler cannot see them. */
static RefParams params(void) {
  static volatile RefParams v = {5.0f, 7.0f, 0.5f, 2.0f, 0.0f, 1.0f, 0.0f, 1, 1, 0};
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
  default: refFbmFolded(pts, out, n); break;
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
  float *out2 = malloc(sizeof(float) * 3 * n);
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
    run(NOISE_RT, pts, out, n);
    run(FBM_RT, pts, out2, n);
    for (int i = 0; i < n; ++i)
      fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g\n", out[3 * i], out[3 * i + 1], out[3 * i + 2],
              out2[3 * i], out2[3 * i + 1], out2[3 * i + 2]);
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
  free(pts), free(out), free(out2), free(t);
  return 0;
}
