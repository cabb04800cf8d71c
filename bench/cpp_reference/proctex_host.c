/* proctex_host.c: runs texcc's generated texture kernel (an output folder's proctex.cl,
 * inline or interp mode, no uniforms kernel) compiled by clang-15 -O3 as native code, one
 * work-item after the other on one thread, over the same points as ref.c. It separates what
 * texcc's generated code costs (the loop budget, the fault guards, the interp dispatch) from
 * what PoCL's build of the same kernel costs: bench/texture_speed.py builds it per folder.
 *
 * Built with -DPROCTEX_POCL it runs a kernel that PoCL built instead: the texcc_proctex.so of
 * PoCL's cache (POCL_CACHE_DIR/.../texcc_proctex/64-1-1-goffs0-smallgrid/), through its
 * work-group function (_pocl_kernel_texcc_proctex_workgroup: the argument values by pointer, one
 * call per group of 64 work-items), so that callgrind can count PoCL's code alone.
 *
 * usage: proctex_host ARGS.BIN [--so KERNEL.SO] [--outputs K] [--points N] [--rounds R]
 *                     [--dump-values FILE]
 *
 * K: the kernel's TEXCC_MAX_OUTPUTS (outputs per hit; default 1).
 *
 * Prints one JSON object: ns per sample per round, the median and the minimum; --dump-values
 * writes output 0's x y z per point (%.9g), as ref.c's --dump-values does. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef PROCTEX_POCL
#include <dlfcn.h>
#endif

typedef float f4 __attribute__((vector_size(16)));

#ifdef PROCTEX_POCL
typedef void (*WorkGroupFn)(void **args, void *ctx, unsigned long gx, unsigned long gy,
                            unsigned long gz);
#else
void texcc_proctex(const void *hits, const int *hitMaterial, int numHits, const unsigned *fakeStack,
                   const void *settings, const f4 *texels, const void *images, f4 *outputs,
                   f4 *scratch, int *faults);

#endif

static unsigned long Gid;
unsigned long clcGlobalId(void) { return Gid; }

#ifdef PROCTEX_POCL
/* One work-group: callgrind's --toggle-collect names this function. */
__attribute__((noinline)) void pocl_run_group(WorkGroupFn wg, void **args, void *ctx,
                                              unsigned long g) {
  wg(args, ctx, g, 0, 0);
}
#endif

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

enum { HIT_F4 = 9, MAX_OUT = 16, SCRATCH_F4 = 256 };

int main(int argc, char **argv) {
  int n = 4096, rounds = 21, outputs = 1;
  const char *argsBin = NULL, *dumpValues = NULL, *so = NULL;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--points") && i + 1 < argc) n = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--outputs") && i + 1 < argc) outputs = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--dump-values") && i + 1 < argc) dumpValues = argv[++i];
    else if (!strcmp(argv[i], "--so") && i + 1 < argc) so = argv[++i];
    else if (!argsBin && argv[i][0] != '-') argsBin = argv[i];
    else {
      fprintf(stderr, "proctex_host: error: unknown argument '%s'\n", argv[i]);
      return 1;
    }
  }
  if (!argsBin || n <= 0 || rounds <= 0 || outputs <= 0 || outputs > MAX_OUT) {
    fprintf(stderr, "proctex_host: error: usage: proctex_host ARGS.BIN [--points N] [--rounds R]\n");
    return 1;
  }
  FILE *f = fopen(argsBin, "rb");
  if (!f) {
    fprintf(stderr, "proctex_host: error: cannot read %s\n", argsBin);
    return 1;
  }
  static unsigned stack[1 << 20];
  size_t words = fread(stack, 4, sizeof stack / 4, f);
  fclose(f);
  (void)words;
  f4 *hits = calloc((size_t)n * HIT_F4, sizeof(f4));
  int *mat = calloc(n, sizeof(int));
  f4 *out = calloc((size_t)n * MAX_OUT, sizeof(f4));
  f4 *scratch = calloc((size_t)n * SCRATCH_F4, sizeof(f4));
  static f4 settings[64], texels[16];
  static int images[64], faults[16];
  double *t = malloc(sizeof(double) * rounds);
  /* The points of ref.c (the same LCG): ObjectPos and WorldPos, as texcc-eval --points. */
  unsigned s = 12345u;
  for (int i = 0; i < n; ++i) {
    float p[3];
    for (int k = 0; k < 3; ++k) {
      s = s * 1664525u + 1013904223u;
      p[k] = (float)(s >> 8) * (2.0f / 16777216.0f) - 1.0f;
    }
    f4 v = {p[0], p[1], p[2], 1.0f};
    hits[(size_t)i * HIT_F4] = hits[(size_t)i * HIT_F4 + 1] = v;
    f4 nrm = {0.0f, 0.0f, 1.0f, 0.0f};
    hits[(size_t)i * HIT_F4 + 2] = hits[(size_t)i * HIT_F4 + 3] = nrm;
  }
#ifdef PROCTEX_POCL
  if (!so || n % 64 != 0) {
    fprintf(stderr, "proctex_host: error: --so KERNEL.SO and --points a multiple of 64\n");
    return 1;
  }
  void *lib = dlopen(so, RTLD_NOW | RTLD_LOCAL);
  WorkGroupFn wg = lib ? (WorkGroupFn)dlsym(lib, "_pocl_kernel_texcc_proctex_workgroup") : NULL;
  if (!wg) {
    fprintf(stderr, "proctex_host: error: %s: no work-group function (%s)\n", so, dlerror());
    return 1;
  }
  static unsigned char ctx[1024];
  const void *hitsP = hits, *matP = mat, *stackP = stack, *settingsP = settings;
  const void *texelsP = texels, *imagesP = images, *outP = out, *scratchP = scratch;
  const void *faultsP = faults;
  void *args[10] = {&hitsP, &matP, &n, &stackP, &settingsP, &texelsP, &imagesP, &outP, &scratchP,
                    &faultsP};
#else
  (void)so;
#endif
  for (int r = -1; r < rounds; ++r) {
    double t0 = now();
#ifdef PROCTEX_POCL
    for (unsigned long g = 0; g < (unsigned long)n / 64; ++g)
      pocl_run_group(wg, args, ctx, g);
#else
    for (Gid = 0; Gid < (unsigned long)n; ++Gid)
      texcc_proctex(hits, mat, n, stack, settings, texels, images, out, scratch, faults);
#endif
    if (r >= 0) t[r] = (now() - t0) * 1e9 / n;
  }
  if (faults[0] != 0) {
    fprintf(stderr, "proctex_host: error: the kernel reported fault kind %d\n", faults[0]);
    return 1;
  }
  if (dumpValues) {
    FILE *o = fopen(dumpValues, "w");
    if (!o) {
      fprintf(stderr, "proctex_host: error: cannot write %s\n", dumpValues);
      return 1;
    }
    for (int i = 0; i < n; ++i) {
      f4 v = out[(size_t)i * outputs];
      fprintf(o, "%.9g %.9g %.9g\n", v[0], v[1], v[2]);
    }
    fclose(o);
  }
  double *sorted = malloc(sizeof(double) * rounds);
  memcpy(sorted, t, sizeof(double) * rounds);
  qsort(sorted, rounds, sizeof(double), cmp);
  printf("{\"points\": %d, \"rounds\": %d, \"medianNsPerSample\": %.2f, \"minNsPerSample\": %.2f, "
         "\"nsPerSample\": [", n, rounds, sorted[rounds / 2], sorted[0]);
  for (int r = 0; r < rounds; ++r) printf("%s%.2f", r ? ", " : "", t[r]);
  printf("]}\n");
  return 0;
}
