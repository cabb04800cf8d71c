/* texcc_device.h: the device-side embedded API of the generated texture kernel (OpenCL C 1.2).
 * texcc copies this file verbatim into every proctex.cl (so the kernel is self-contained);
 * the user's readAttr/readSetting/tex2D calls are lowered by texcc to the accessors below, and
 * every user function takes the hit context as a first parameter (TEXCC_CTX_PARAM). */
#ifndef TEXCC_DEVICE_H
#define TEXCC_DEVICE_H

typedef int sam2D; /* an image index into TexccCtx::images */

/* floor, ceil and trunc as the compiler's rounding instructions (x86: roundss/roundps). PoCL's
 * kernel library computes them in software, with a branch in the scalar forms (a float-to-int
 * round trip, a fix-up, tests for infinities and large values): 72 floors per sample of a Noise
 * Texture of Detail 7 in Color. The results are exact either way, so the values are the same
 * (codegen/device-rounding.test). Noise 3D Color Detail 7 on PoCL, one thread: inline 958 ->
 * 759 ns per sample, interp 747 -> 646 (bench/texture-speed.md). */
#if defined(__clang__) && __has_builtin(__builtin_elementwise_floor)
/* PoCL's kernel header defines them as macros too: replaced without a "macro redefined"
 * warning (PoCL prints the count of a build's warnings on stderr). */
#undef floor
#undef ceil
#undef trunc
#define floor(x) __builtin_elementwise_floor(x)
#define ceil(x) __builtin_elementwise_ceil(x)
#define trunc(x) __builtin_elementwise_trunc(x)
#endif

/* The loop budget: how many loop iterations (all loops of all nodes together) one work-item may
 * run per launch; texcc --loop-budget N defines it before this header. */
#ifndef TEXCC_LOOP_BUDGET
#define TEXCC_LOOP_BUDGET 16777216u
#endif
/* The budget is spent in slices: at the end of each the work-item looks at the launch's fault
 * record and stops its loops when another work-item has faulted (the launch is an error and its
 * values are never used). An endless loop then costs one work-item's budget and a slice of each
 * of the others, not every work-item's budget (64x64 hits at the default budget: 54 s before;
 * bench/loop-budget.md). The first slice takes what the division leaves over. */
#define TEXCC_LOOP_SLICE 4096u
#define TEXCC_LOOP_FIRST_SLICE                                                                     \
  (TEXCC_LOOP_BUDGET % TEXCC_LOOP_SLICE != 0u                                                      \
       ? TEXCC_LOOP_BUDGET % TEXCC_LOOP_SLICE                                                      \
       : (TEXCC_LOOP_BUDGET < TEXCC_LOOP_SLICE ? TEXCC_LOOP_BUDGET : TEXCC_LOOP_SLICE))
#define TEXCC_LOOP_SLICES ((TEXCC_LOOP_BUDGET - TEXCC_LOOP_FIRST_SLICE) / TEXCC_LOOP_SLICE)
#ifndef TEXCC_CHECKS
#define TEXCC_CHECKS 1 /* 0: texcc --no-checks (A/B measurement only) */
#endif

/* The safety state of one work-item (docs/reliability.md "User code"): what is left of its loop
 * budget, which node runs (TEXCC_FAULT_AT), and where a tripped check records the launch's
 * first fault (texcc_abi.h). The kernel's prologue sets the fields up to badLine; the details
 * after it are written only when line or badLine is first set and read only then, and are
 * volatile so that they stay in memory: otherwise the device compiler carries a copy of each
 * through every loop and every case of the interp dispatch (rust interp: 3745.8 instructions
 * per hit against 3702.8 with them volatile, 3662.7 unchecked; bench/loop-budget.md). */
typedef struct TexccGuard {
  uint loopsLeft;  /* of the slice being spent */
  uint slicesLeft; /* whole slices after it */
  uint at;
  int hit;
  int material;
  __global int *fault;
  int line;    /* of the loop that spent the budget; 0: none did; -1: stopped (another's fault) */
  int badLine; /* of the first __global array read out of bounds; 0: none was */
  volatile uint lineAt;    /* at, when the budget was spent */
  volatile uint badAt;     /* at, when the read was out of bounds */
  volatile int badIndex;   /* its index (clamped to the int range) */
  volatile uint badLength; /* and its array's length */
} TexccGuard;

typedef struct TexccCtx {
  TexccHitAttrs hit;
  __global const TexccSettings *settings;
  __global const float4 *texels;
  __global const TexccImageInfo *images;
  TexccGuard *guard;
#if TEXCC_POSITION_OFFSET
  /* A graph with a bump node (docs/graph.md "Bump"): what readAttr("WorldPos") and
   * readAttr("ObjectPos") add to the hit's position while a node of the height runs at a
   * moved position; zero otherwise (texcc_position_offset sets both). */
  float3 worldOffset;
  float3 objectOffset;
#endif
} TexccCtx;

#define TEXCC_CTX_PARAM const TexccCtx *texcc_ctx
#define TEXCC_CTX_ARG texcc_ctx
/* Every user function and every evaluation helper is inlined into the kernel: a call left in
 * place costs a GPU backend registers and scratch around it (clang-15, gfx90a: scratches in
 * shape mode 51 VGPRs and 8 B of scratch with voronoiSearch called, 36 and 0 B inlined).
 * texrender's first build of a kernel not in its program cache defines it as noinline (the
 * "first" build, docs/runtime.md "Tiers"): PoCL then compiles each function once and vectorises
 * nothing across work-items, 6-8x faster to build, slower per hit, the same values. */
#ifndef TEXCC_FN
#define TEXCC_FN __attribute__((always_inline))
#endif

/* Records a fault unless one was recorded before in this launch (one compare-exchange). */
static inline void texcc_fault(const TexccCtx *c, int kind, int line, uint at, int detail,
                               int extra) {
  __global int *f = c->guard->fault;
  if (atomic_cmpxchg(f + TEXCC_FAULT_KIND, TEXCC_FAULT_NONE, kind) != TEXCC_FAULT_NONE)
    return;
  f[TEXCC_FAULT_LINE] = line;
  f[TEXCC_FAULT_AT] = (int)at;
  f[TEXCC_FAULT_HIT] = c->guard->hit;
  f[TEXCC_FAULT_DETAIL] = detail;
  f[TEXCC_FAULT_EXTRA] = extra;
  f[TEXCC_FAULT_MATERIAL] = c->guard->material;
}

/* The end of a slice: true when a new one starts. None left: the loop's line is kept (the
 * budget is spent); another work-item's fault recorded: the loops stop without a fault of this
 * one (line -1). */
static bool texcc_loop_next_slice(const TexccCtx *c, int line) {
  TexccGuard *g = c->guard;
  if (g->slicesLeft != 0u &&
      ((volatile __global int *)g->fault)[TEXCC_FAULT_KIND] == TEXCC_FAULT_NONE) {
    --g->slicesLeft;
    g->loopsLeft = TEXCC_LOOP_SLICE;
    return true;
  }
  if (g->line == 0) {
    g->line = g->slicesLeft != 0u ? -1 : line;
    g->lineAt = g->at;
  }
  g->loopsLeft = 0u;
  g->slicesLeft = 0u;
  return false;
}

/* Charges n iterations that the slice being spent does not hold (texcc_loop_charge). */
static bool texcc_loop_charge_slices(const TexccCtx *c, uint n, int line) {
  TexccGuard *g = c->guard;
  const uint total = g->loopsLeft + g->slicesLeft * TEXCC_LOOP_SLICE;
  if (total >= n && ((volatile __global int *)g->fault)[TEXCC_FAULT_KIND] == TEXCC_FAULT_NONE) {
    g->slicesLeft = (total - n) / TEXCC_LOOP_SLICE;
    g->loopsLeft = (total - n) % TEXCC_LOOP_SLICE;
    return true;
  }
  if (g->line == 0) {
    g->line = total >= n ? -1 : line;
    g->lineAt = g->at;
  }
  g->loopsLeft = 0u;
  g->slicesLeft = 0u;
  return false;
}

/* texcc ends the condition of every user loop with `&& texcc_loop_continues(texcc_ctx,
 * __LINE__)`: each iteration spends one of the work-item's budget. With none left the loop
 * ends, and so does every loop around it at its next test; the first such loop's line and
 * node are kept for texcc_report_fault (private stores only: no atomic inside user loops). */
static inline bool texcc_loop_continues(const TexccCtx *c, int line) {
  TexccGuard *g = c->guard;
  if (!TEXCC_CHECKS || g->loopsLeft != 0u || texcc_loop_next_slice(c, line)) {
    --g->loopsLeft;
    return true;
  }
  return false;
}

/* A loop whose trip count texcc knows (a constant `for`) is charged once before it runs:
 * `if (!texcc_loop_charge(texcc_ctx, N, __LINE__)) {} else for (...)`. Not enough budget left:
 * the loop does not run, none is left, and its line is kept as for texcc_loop_continues. */
static inline bool texcc_loop_charge(const TexccCtx *c, uint n, int line) {
  TexccGuard *g = c->guard;
  if (!TEXCC_CHECKS || g->loopsLeft >= n) {
    g->loopsLeft -= n;
    return true;
  }
  return texcc_loop_charge_slices(c, n, line);
}

/* A constant `for` of N >= 1 iterations whose start is a literal is charged without a branch
 * before it (texcc/lib/frontend/Safety.cpp, constantForm): `for (int texcc_bad =
 * texcc_loop_charge_once(texcc_ctx, N, __LINE__), i = texcc_bad ? (LAST) : (A); ...) if
 * (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else BODY`. Not enough budget left: none
 * is left, and the loop makes one iteration from its last value that records the fault (as
 * texcc_loop_continues does) and runs nothing of BODY. */
static inline int texcc_loop_charge_once(const TexccCtx *c, uint n, int line) {
  TexccGuard *g = c->guard;
  const uint left = g->loopsLeft;
  if (!TEXCC_CHECKS || left >= n) {
    g->loopsLeft = left - n;
    return 0;
  }
  return texcc_loop_charge_slices(c, n, line) ? 0 : line;
}

static inline void texcc_loop_fault(const TexccCtx *c, int line) {
  TexccGuard *g = c->guard;
  if (g->line == 0) {
    g->line = line;
    g->lineAt = g->at;
  }
}

/* A loop whose trip count is a span texcc can compute before it runs (a `for` over a bound that
 * the loop does not change, e.g. fbm's octaves): `if (!texcc_loop_charge_span(texcc_ctx,
 * (long)(n) - (long)(a), __LINE__)) {} else for (int i = a; i < n; ++i)`, charged max(0, span)
 * once as texcc_loop_charge. */
static inline bool texcc_loop_charge_span(const TexccCtx *c, long span, int line) {
  return texcc_loop_charge(c, span <= 0 ? 0u : span >= (long)UINT_MAX ? UINT_MAX : (uint)span,
                           line);
}

/* The same for such a loop with constant loops nested in it, which it charges for (they carry
 * no charge of their own): `texcc_loop_charge_nest(texcc_ctx, SPAN, PER, __LINE__)`, PER being
 * the iterations each of its iterations accounts for (1 plus the nested loops' counts);
 * charged max(0, span) * PER, at most UINT_MAX. */
static inline bool texcc_loop_charge_nest(const TexccCtx *c, long span, uint per, int line) {
  const ulong n = span <= 0 ? 0ul : (ulong)min(span, (long)UINT_MAX) * (ulong)per;
  return texcc_loop_charge(c, n >= (ulong)UINT_MAX ? UINT_MAX : (uint)n, line);
}

/* texcc turns every read `p[i]` of a __global array parameter into
 * `texcc_read_T(texcc_ctx, p, (i), texcc_n_p, __LINE__)`, texcc_n_p being the array's length
 * (a hidden parameter texcc adds). Out of range: 0, and the first such read's line, node, index
 * and length are kept for texcc_report_fault (private stores only, as for loops). */
static inline bool texcc_index_ok(const TexccCtx *c, long i, uint n, int line) {
  if (!TEXCC_CHECKS || (ulong)i < (ulong)n)
    return true;
  TexccGuard *g = c->guard;
  if (g->badLine == 0) {
    g->badLine = line;
    g->badAt = g->at;
    g->badIndex = (int)clamp(i, (long)INT_MIN, (long)INT_MAX);
    g->badLength = n;
  }
  return false;
}
#define TEXCC_CHECKED_READ(T)                                                                  \
  static inline T texcc_read_##T(const TexccCtx *c, __global const T *p, long i, uint n,      \
                                 int line) {                                                   \
    return texcc_index_ok(c, i, n, line) ? p[i] : (T)(0);                                      \
  }
TEXCC_CHECKED_READ(float)
TEXCC_CHECKED_READ(float2)
TEXCC_CHECKED_READ(float3)
TEXCC_CHECKED_READ(float4)
TEXCC_CHECKED_READ(int)
TEXCC_CHECKED_READ(int2)
TEXCC_CHECKED_READ(int3)
TEXCC_CHECKED_READ(int4)
TEXCC_CHECKED_READ(uint)
TEXCC_CHECKED_READ(uint2)
TEXCC_CHECKED_READ(uint3)
TEXCC_CHECKED_READ(uint4)
#undef TEXCC_CHECKED_READ

/* texcc turns a subscript `a[i]` of a private (or __constant) array of N elements whose index
 * it cannot prove in range into `a[texcc_index(texcc_ctx, (i), Nu, __LINE__)]`: out of range
 * the index is 0 (a read reads, a write writes, the first element) and the fault is kept as
 * for a __global read. */
static inline long texcc_index(const TexccCtx *c, long i, uint n, int line) {
  return texcc_index_ok(c, i, n, line) ? i : 0;
}

/* At the end of the kernel: the work-item's fault, if any, into the fault record (a loop past
 * its budget first: its out-of-range reads may be a consequence). */
static inline void texcc_report_fault(const TexccCtx *c) {
  if (TEXCC_CHECKS && c->guard->line > 0)
    texcc_fault(c, TEXCC_FAULT_LOOP_BUDGET, c->guard->line, c->guard->lineAt,
                (int)TEXCC_LOOP_BUDGET, 0);
  else if (TEXCC_CHECKS && c->guard->badLine != 0)
    texcc_fault(c, TEXCC_FAULT_INDEX, c->guard->badLine, c->guard->badAt, c->guard->badIndex,
                (int)c->guard->badLength);
}

/* readAttr("Name") lowers to texcc_attr_Name(texcc_ctx). */
#if TEXCC_POSITION_OFFSET
static inline float3 texcc_attr_WorldPos(const TexccCtx *c) {
  return c->hit.worldPos.xyz + c->worldOffset;
}
static inline float3 texcc_attr_ObjectPos(const TexccCtx *c) {
  return c->hit.objectPos.xyz + c->objectOffset;
}
#else
static inline float3 texcc_attr_WorldPos(const TexccCtx *c) { return c->hit.worldPos.xyz; }
static inline float3 texcc_attr_ObjectPos(const TexccCtx *c) { return c->hit.objectPos.xyz; }
#endif
static inline float3 texcc_attr_Normal(const TexccCtx *c) { return c->hit.normal.xyz; }
static inline float3 texcc_attr_GeomNormal(const TexccCtx *c) { return c->hit.geomNormal.xyz; }
static inline float3 texcc_attr_Tangent(const TexccCtx *c) { return c->hit.tangent.xyz; }
static inline float2 texcc_attr_TexCoord0(const TexccCtx *c) { return c->hit.uvAO.xy; }
static inline float texcc_attr_AO(const TexccCtx *c) { return c->hit.uvAO.z; }
static inline float3 texcc_attr_ViewDir(const TexccCtx *c) { return c->hit.viewDir.xyz; }
static inline float texcc_attr_TangentSign(const TexccCtx *c) { return c->hit.tangent.w; }
static inline float texcc_attr_Backfacing(const TexccCtx *c) { return c->hit.uvAO.w; }

/* readSetting("Name") lowers to texcc_setting_Name(texcc_ctx). */
static inline float texcc_setting_Time(const TexccCtx *c) { return c->settings->time; }
static inline int texcc_setting_Frame(const TexccCtx *c) { return c->settings->frame; }
static inline float3 texcc_setting_CameraPos(const TexccCtx *c) { return c->settings->cameraPos.xyz; }

#if TEXCC_POSITION_OFFSET
/* Bump (docs/graph.md "Bump"), offset as Cycles 5.0 offsets a Bump node's height (its
 * svm_node_set_bump and the height's dx/dy copies): the moved evaluations go
 * TEXCC_BUMP_FILTER_WIDTH (the node's Filter Width, 0.1) of the ray's footprint along two fixed
 * orthogonal directions in the plane of the geometric normal (texcc_bump_frame), not along the
 * surface's tangent; the step is at least 1e-4 of the position's magnitude (float
 * resolution). */
#ifndef TEXCC_BUMP_FILTER_WIDTH
#define TEXCC_BUMP_FILTER_WIDTH 0.1f
#endif
/* The ray's footprint at the hit, as Cycles' compact ray differential of a camera ray: the
 * distance times the mean length of the unit ray direction's change over one pixel in x and
 * in y, pixelAngle x 0.5 (sqrt(1 + y^2) + sqrt(1 + x^2)) / (1 + x^2 + y^2) at the film
 * position (x, y) (tangents of the angles off the view direction) the hit projects to: 1 x
 * pixelAngle at the image centre, 0.69 x at the corner of a 60-degree square view. A hit
 * behind the camera (reached after a bounce), or settings without the camera's axes, takes
 * the centre's value. Cycles' footprint after a bounce grows with the path's length; this one
 * with the distance from the camera. */
static inline float texcc_bump_footprint(const TexccCtx *c) {
  const float3 v = c->hit.worldPos.xyz - c->settings->cameraPos.xyz;
  const float z = dot(v, c->settings->cameraForward.xyz);
  float f = 1.0f;
  if (z > 0.0f) {
    const float x = dot(v, c->settings->cameraRight.xyz) / z;
    const float y = dot(v, c->settings->cameraUp.xyz) / z;
    f = 0.5f * (sqrt(1.0f + y * y) + sqrt(1.0f + x * x)) / (1.0f + x * x + y * y);
  }
  return c->settings->pixelAngle * length(v) * f;
}
static inline float texcc_bump_step(const TexccCtx *c) {
  const float3 a = fabs(c->hit.worldPos.xyz);
  return fmax(TEXCC_BUMP_FILTER_WIDTH * texcc_bump_footprint(c),
              1e-4f * (1.0f + fmax(a.x, fmax(a.y, a.z))));
}
/* The offset directions: Cycles' orthonormal pair of the geometric normal n (facing the ray),
 * a = normalize((1, 1, 1) x n) ((-1, 1, 1) x n when n's components are equal) and b = n x a;
 * the shading normal where no geometric normal is filled. hit_attributes.cl's objectTangent and
 * objectBitangent are the same pair through the object's inverse transform. */
static inline float3 texcc_bump_frame(const TexccCtx *c, float3 *b) {
  float3 n = c->hit.geomNormal.xyz;
  if (!(dot(n, n) > 0.25f))
    n = c->hit.normal.xyz;
  const float3 a = normalize((n.x != n.y || n.x != n.z)
                                 ? (float3)(n.z - n.y, n.x - n.z, n.y - n.x)
                                 : (float3)(n.z - n.y, n.x + n.z, -n.y - n.x));
  *b = cross(n, a);
  return a;
}
/* Before a node runs: k = 0 the hit's position, 1 moved by one step along the frame's a, 2
 * along b (in object space by the hit's objectTangent/objectBitangent, the same vectors through
 * the object's inverse transform). The context is the kernel's own (non-const) local. */
static inline void texcc_position_offset(const TexccCtx *c, int k) {
  TexccCtx *m = (TexccCtx *)c;
  m->worldOffset = m->objectOffset = (float3)(0.0f);
  if (k == 0)
    return;
  const float e = texcc_bump_step(c);
  float3 b;
  const float3 a = texcc_bump_frame(c, &b);
  m->worldOffset = e * (k == 1 ? a : b);
  m->objectOffset = e * (k == 1 ? c->hit.objectTangent.xyz : c->hit.objectBitangent.xyz);
}
/* The bump node: the height h at the hit, hx and hy one step along a and b. The perturbed
 * normal from the height's surface gradient (Mikkelsen 2010, the method of Cycles' Bump node):
 * the gradient over the step's parallelogram, scaled by distance, tilts the input normal;
 * strength (0..1) blends towards it. */
static inline float3 texcc_bump(const TexccCtx *c, float h, float strength, float distance,
                                float3 normal, float hx, float hy) {
  const float e = texcc_bump_step(c);
  float3 b;
  const float3 a = texcc_bump_frame(c, &b);
  const float3 dx = e * a, dy = e * b;
  const float3 rx = cross(dy, normal), ry = cross(normal, dx);
  const float det = dot(dx, rx);
  const float3 grad = (hx - h) * rx + (hy - h) * ry;
  const float3 tilted = normalize(fabs(det) * normal - distance * sign(det) * grad);
  const float s = clamp(strength, 0.0f, 1.0f);
  return normalize(s * tilted + (1.0f - s) * normal);
}
#endif

/* Attribute by id, widened to float4 (the interpreter's attribute arguments). */
static inline float4 texcc_attr_by_id(const TexccCtx *c, uint id) {
  switch (id) {
  case TEXCC_ATTR_WORLDPOS: return c->hit.worldPos;
  case TEXCC_ATTR_OBJECTPOS: return c->hit.objectPos;
  case TEXCC_ATTR_NORMAL: return c->hit.normal;
  case TEXCC_ATTR_GEOMNORMAL: return c->hit.geomNormal;
  case TEXCC_ATTR_TANGENT: return c->hit.tangent;
  case TEXCC_ATTR_TEXCOORD0: return (float4)(c->hit.uvAO.xy, 0.0f, 0.0f);
  case TEXCC_ATTR_AO: return (float4)(c->hit.uvAO.z, 0.0f, 0.0f, 0.0f);
  case TEXCC_ATTR_VIEWDIR: return c->hit.viewDir;
  case TEXCC_ATTR_TANGENTSIGN: return (float4)(c->hit.tangent.w, 0.0f, 0.0f, 0.0f);
  case TEXCC_ATTR_BACKFACING: return (float4)(c->hit.uvAO.w, 0.0f, 0.0f, 0.0f);
  default: return (float4)(0.0f);
  }
}

static inline float4 texcc_texel(__global const float4 *texels, TexccImageInfo im, int x, int y) {
  x = x % im.width;
  if (x < 0) x += im.width;
  y = y % im.height;
  if (y < 0) y += im.height;
  return texels[im.offset + y * im.width + x];
}

/* tex2D(s, uv) lowers to texcc_tex2D(texcc_ctx, s, uv): bilinear, wrapping in both axes,
 * linear RGBA. An out-of-range image index reads magenta, never out of bounds. */
static inline float4 texcc_tex2D(const TexccCtx *c, sam2D s, float2 uv) {
  if (s < 0) return (float4)(1.0f, 0.0f, 1.0f, 1.0f);
  TexccImageInfo im = c->images[s];
  if (im.width <= 0 || im.height <= 0) return (float4)(1.0f, 0.0f, 1.0f, 1.0f);
  float fx = uv.x * (float)im.width - 0.5f;
  float fy = uv.y * (float)im.height - 0.5f;
  float x0f = floor(fx), y0f = floor(fy);
  float tx = fx - x0f, ty = fy - y0f;
  int x0 = (int)x0f, y0 = (int)y0f;
  float4 a = texcc_texel(c->texels, im, x0, y0);
  float4 b = texcc_texel(c->texels, im, x0 + 1, y0);
  float4 d = texcc_texel(c->texels, im, x0, y0 + 1);
  float4 e = texcc_texel(c->texels, im, x0 + 1, y0 + 1);
  return mix(mix(a, b, tx), mix(d, e, tx), ty);
}

/* Blender's extension of an integer texel coordinate: 0 Repeat, 1 Extend, 2 Clip (-1: outside,
 * reads 0), 3 Mirror. */
static inline int texcc_extend(int x, int n, int extension) {
  if (extension == 1) return clamp(x, 0, n - 1);
  if (extension == 2) return x < 0 || x >= n ? -1 : x;
  if (extension == 3) {
    const int m = abs(x + (x < 0 ? 1 : 0)) % (2 * n);
    return m >= n ? 2 * n - m - 1 : m;
  }
  x = x % n;
  return x < 0 ? x + n : x;
}

/* A texel as Cycles interpolates it: an sRGB image's colour re-encoded to sRGB (Cycles keeps
 * such images encoded and decodes after interpolation), a colour image's alpha associated; in
 * an 8- or 16-bit image as Cycles does it on the integers, k * a / 255 (65535) rounded down. */
static inline float4 texcc_texel_filtered(__global const float4 *texels, TexccImageInfo im,
                                          int x, int y) {
  if (x < 0 || y < 0) return (float4)(0.0f);
  float4 t = texels[im.offset + y * im.width + x];
  if (im.flags & TEXCC_IMAGE_SRGB) {
    float3 v = fmax(t.xyz, 0.0f);
    t.xyz = select(1.055f * pow(v, (float3)(1.0f / 2.4f)) - 0.055f, 12.92f * v,
                   isless(v, (float3)(0.0031308f)));
  }
  if (!(im.flags & TEXCC_IMAGE_DATA) && t.w != 1.0f) {
    if (im.flags & (TEXCC_IMAGE_BYTES | TEXCC_IMAGE_SHORTS)) {
      const float m = (im.flags & TEXCC_IMAGE_BYTES) ? 255.0f : 65535.0f;
      t.xyz = floor(rint(t.xyz * m) * rint(t.w * m) / m) / m;
    } else {
      t.xyz *= t.w;
    }
  }
  return t;
}

static inline float4 texcc_bspline(float t) {
  const float s = 1.0f - t;
  return (float4)(s * s * s, (3.0f * t * t * t - 6.0f * t * t + 4.0f),
                  (-3.0f * t * t * t + 3.0f * t * t + 3.0f * t + 1.0f), t * t * t) / 6.0f;
}

/* tex2DFiltered(s, uv, interpolation, extension, straight) lowers to texcc_tex2DFiltered(
 * texcc_ctx, ...): Blender's Image Texture lookup (uv as tex2D's, v = 0 at the top row).
 * interpolation 0 Linear, 1 Closest, 2 Cubic (uniform cubic B-spline, as Cycles'); extension
 * 0 Repeat, 1 Extend, 2 Clip (transparent black outside), 3 Mirror. A colour image (not
 * Non-Color) is interpolated with alpha associated and, with straight != 0, divided by the
 * interpolated alpha afterwards (Cycles does so when the node's Alpha output is used); an sRGB
 * image is interpolated in sRGB and decoded after, as Cycles reads image files. Returns linear
 * RGBA. */
static inline float4 texcc_tex2DFiltered(const TexccCtx *c, sam2D s, float2 uv,
                                         int interpolation, int extension, int straight) {
  if (s < 0) return (float4)(1.0f, 0.0f, 1.0f, 1.0f);
  TexccImageInfo im = c->images[s];
  if (im.width <= 0 || im.height <= 0) return (float4)(1.0f, 0.0f, 1.0f, 1.0f);
  float4 r;
  if (interpolation == 1) {
    const int x = texcc_extend((int)floor(uv.x * (float)im.width), im.width, extension);
    const int y = texcc_extend((int)floor(uv.y * (float)im.height), im.height, extension);
    r = texcc_texel_filtered(c->texels, im, x, y);
  } else {
    const float fx = uv.x * (float)im.width - 0.5f, fy = uv.y * (float)im.height - 0.5f;
    const float x0f = floor(fx), y0f = floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = (int)x0f, y0 = (int)y0f;
    if (interpolation == 2) {
      const float4 wx = texcc_bspline(tx), wy = texcc_bspline(ty);
      const float wxs[4] = {wx.x, wx.y, wx.z, wx.w}, wys[4] = {wy.x, wy.y, wy.z, wy.w};
      r = (float4)(0.0f);
      for (int j = 0; j < 4; ++j) {
        const int y = texcc_extend(y0 - 1 + j, im.height, extension);
        float4 row = (float4)(0.0f);
        for (int i = 0; i < 4; ++i)
          row += wxs[i] * texcc_texel_filtered(c->texels, im,
                                               texcc_extend(x0 - 1 + i, im.width, extension), y);
        r += wys[j] * row;
      }
    } else {
      const int xa = texcc_extend(x0, im.width, extension);
      const int xb = texcc_extend(x0 + 1, im.width, extension);
      const int ya = texcc_extend(y0, im.height, extension);
      const int yb = texcc_extend(y0 + 1, im.height, extension);
      r = mix(mix(texcc_texel_filtered(c->texels, im, xa, ya),
                  texcc_texel_filtered(c->texels, im, xb, ya), tx),
              mix(texcc_texel_filtered(c->texels, im, xa, yb),
                  texcc_texel_filtered(c->texels, im, xb, yb), tx),
              ty);
    }
  }
  if (straight && !(im.flags & TEXCC_IMAGE_DATA) && r.w != 0.0f && r.w != 1.0f)
    r.xyz /= r.w;
  if (im.flags & TEXCC_IMAGE_SRGB) {
    const float3 v = r.xyz;
    r.xyz = select(pow((v + 0.055f) / 1.055f, (float3)(2.4f)), v / 12.92f,
                   isless(v, (float3)(0.04045f)));
    r.xyz = select(r.xyz, (float3)(0.0f), isless(v, (float3)(0.0f)));
  }
  return r;
}

#endif
