// HostPrelude.hpp: the OpenCL C 1.2 vocabulary that texture code uses, for C++17 (g++), over GLM.
// texcc copies it verbatim into every proctex.cpp (--target=host), after texcc_abi.h and before
// the user code, so that the same user text compiles as C++:
//   - float2..4, int2..4, uint2..4 are GLM vectors with member swizzles (.xy, .xyz, ...);
//   - OpenCL vector literals `(float3)(a, b)` are rewritten by texcc to texcc_make_float3(a, b),
//     non-template overloads that accept swizzles and every OpenCL component split;
//   - the builtins (math, common, geometric, relational select, conversions) are non-template
//     overloads per type, so that swizzle proxies convert implicitly;
//   - __global, __constant, __private, __local are empty: the host has one address space;
//   - TexccCtx and the readAttr/readSetting/tex2D accessors mirror kernels/common/texcc_device.h.
// Everything the user code sees lives in namespace texcc_cl, which hides the C library's double
// overloads (sin, fabs, ...) so that float arithmetic stays float, as on the device.
#ifndef TEXCC_HOST_PRELUDE_HPP
#define TEXCC_HOST_PRELUDE_HPP

#include <cmath>
#include <cstdint>
#include <cstring>

// Member swizzles (v.xyz rather than v.xyz()) need GLM's anonymous-struct storage, which GLM
// enables for GCC and Clang only together with its SIMD intrinsics.
#define GLM_FORCE_SWIZZLE
#define GLM_FORCE_INTRINSICS
// Only the vector types: the builtins below are texcc's own (OpenCL semantics), and the rest of
// GLM would triple the compile time of every proctex.cpp.
#include <glm/ext/vector_int2.hpp>
#include <glm/ext/vector_int3.hpp>
#include <glm/ext/vector_int4.hpp>
#include <climits>
#include <glm/ext/vector_uint2.hpp>
#include <glm/ext/vector_uint3.hpp>
#include <glm/ext/vector_uint4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#define __global
#define __constant
#define __private
#define __local
#define __kernel
#define __read_only
#define __write_only

namespace texcc_cl {

typedef unsigned int uint;
typedef unsigned char uchar;
typedef glm::vec2 float2;
typedef glm::vec3 float3;
typedef glm::vec4 float4;
typedef glm::ivec2 int2;
typedef glm::ivec3 int3;
typedef glm::ivec4 int4;
typedef glm::uvec2 uint2;
typedef glm::uvec3 uint3;
typedef glm::uvec4 uint4;

// ---- vector literals: (floatN)(...) becomes texcc_make_floatN(...) ----
#define TEXCC_MAKE_VECTORS(S, V2, V3, V4)                                                          \
  inline V2 texcc_make_##V2(S a) { return V2(a); }                                                \
  inline V2 texcc_make_##V2(S a, S b) { return V2(a, b); }                                        \
  inline V2 texcc_make_##V2(V2 a) { return a; }                                                   \
  inline V3 texcc_make_##V3(S a) { return V3(a); }                                                \
  inline V3 texcc_make_##V3(S a, S b, S c) { return V3(a, b, c); }                                \
  inline V3 texcc_make_##V3(V2 a, S b) { return V3(a.x, a.y, b); }                                \
  inline V3 texcc_make_##V3(S a, V2 b) { return V3(a, b.x, b.y); }                                \
  inline V3 texcc_make_##V3(V3 a) { return a; }                                                   \
  inline V4 texcc_make_##V4(S a) { return V4(a); }                                                \
  inline V4 texcc_make_##V4(S a, S b, S c, S d) { return V4(a, b, c, d); }                        \
  inline V4 texcc_make_##V4(V2 a, S b, S c) { return V4(a.x, a.y, b, c); }                        \
  inline V4 texcc_make_##V4(S a, V2 b, S c) { return V4(a, b.x, b.y, c); }                        \
  inline V4 texcc_make_##V4(S a, S b, V2 c) { return V4(a, b, c.x, c.y); }                        \
  inline V4 texcc_make_##V4(V2 a, V2 b) { return V4(a.x, a.y, b.x, b.y); }                        \
  inline V4 texcc_make_##V4(V3 a, S b) { return V4(a.x, a.y, a.z, b); }                           \
  inline V4 texcc_make_##V4(S a, V3 b) { return V4(a, b.x, b.y, b.z); }                           \
  inline V4 texcc_make_##V4(V4 a) { return a; }
TEXCC_MAKE_VECTORS(float, float2, float3, float4)
TEXCC_MAKE_VECTORS(int, int2, int3, int4)
TEXCC_MAKE_VECTORS(uint, uint2, uint3, uint4)
#undef TEXCC_MAKE_VECTORS

// ---- component-wise helpers (internal) ----
template <class V, class F> inline V texcc_cw1(V A, F Fn) {
  for (int I = 0; I < V::length(); ++I)
    A[I] = Fn(A[I]);
  return A;
}
template <class V, class F> inline V texcc_cw2(V A, V B, F Fn) {
  for (int I = 0; I < V::length(); ++I)
    A[I] = Fn(A[I], B[I]);
  return A;
}
template <class V, class F> inline V texcc_cw3(V A, V B, V C, F Fn) {
  for (int I = 0; I < V::length(); ++I)
    A[I] = Fn(A[I], B[I], C[I]);
  return A;
}

// ---- scalar float builtins ----
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float tan(float x) { return std::tan(x); }
inline float asin(float x) { return std::asin(x); }
inline float acos(float x) { return std::acos(x); }
inline float atan(float x) { return std::atan(x); }
inline float sinh(float x) { return std::sinh(x); }
inline float cosh(float x) { return std::cosh(x); }
inline float tanh(float x) { return std::tanh(x); }
inline float exp(float x) { return std::exp(x); }
inline float exp2(float x) { return std::exp2(x); }
inline float log(float x) { return std::log(x); }
inline float log2(float x) { return std::log2(x); }
inline float log10(float x) { return std::log10(x); }
inline float sqrt(float x) { return std::sqrt(x); }
inline float rsqrt(float x) { return 1.0f / std::sqrt(x); }
inline float fabs(float x) { return std::fabs(x); }
inline float floor(float x) { return std::floor(x); }
inline float ceil(float x) { return std::ceil(x); }
inline float round(float x) { return std::round(x); }
inline float trunc(float x) { return std::trunc(x); }
inline float sign(float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }
inline float radians(float x) { return x * 0.017453292519943295f; }
inline float degrees(float x) { return x * 57.29577951308232f; }
inline float fract(float x, float *ip) {
  float F = std::floor(x);
  *ip = F;
  return std::fmin(x - F, 0x1.fffffep-1f);
}
inline float fract(float x) {
  float I;
  return fract(x, &I);
}
inline float pow(float x, float y) { return std::pow(x, y); }
inline float powr(float x, float y) { return std::pow(x, y); }
inline float pown(float x, int n) { return std::pow(x, static_cast<float>(n)); }
inline float fmod(float x, float y) { return std::fmod(x, y); }
inline float atan2(float y, float x) { return std::atan2(y, x); }
inline float hypot(float x, float y) { return std::hypot(x, y); }
inline float copysign(float x, float y) { return std::copysign(x, y); }
inline float fmin(float x, float y) { return std::fmin(x, y); }
inline float fmax(float x, float y) { return std::fmax(x, y); }
inline float min(float x, float y) { return y < x ? y : x; }
inline float max(float x, float y) { return x < y ? y : x; }
inline float step(float edge, float x) { return x < edge ? 0.0f : 1.0f; }
inline float clamp(float x, float lo, float hi) { return fmin(fmax(x, lo), hi); }
inline float mix(float a, float b, float t) { return a + (b - a) * t; }
inline float mad(float a, float b, float c) { return a * b + c; }
inline float fma(float a, float b, float c) { return std::fma(a, b, c); }
inline float smoothstep(float e0, float e1, float x) {
  float T = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return T * T * (3.0f - 2.0f * T);
}
inline float dot(float a, float b) { return a * b; }
inline float length(float a) { return std::fabs(a); }
inline float distance(float a, float b) { return std::fabs(a - b); }
inline float normalize(float a) { return sign(a); }

// ---- the same, component-wise on float2..4 (and vector-scalar forms OpenCL allows) ----
#define TEXCC_VEC_BUILTINS(V)                                                                      \
  inline V sin(V x) { return texcc_cw1(x, [](float a) { return sin(a); }); }                      \
  inline V cos(V x) { return texcc_cw1(x, [](float a) { return cos(a); }); }                      \
  inline V tan(V x) { return texcc_cw1(x, [](float a) { return tan(a); }); }                      \
  inline V asin(V x) { return texcc_cw1(x, [](float a) { return asin(a); }); }                    \
  inline V acos(V x) { return texcc_cw1(x, [](float a) { return acos(a); }); }                    \
  inline V atan(V x) { return texcc_cw1(x, [](float a) { return atan(a); }); }                    \
  inline V sinh(V x) { return texcc_cw1(x, [](float a) { return sinh(a); }); }                    \
  inline V cosh(V x) { return texcc_cw1(x, [](float a) { return cosh(a); }); }                    \
  inline V tanh(V x) { return texcc_cw1(x, [](float a) { return tanh(a); }); }                    \
  inline V exp(V x) { return texcc_cw1(x, [](float a) { return exp(a); }); }                      \
  inline V exp2(V x) { return texcc_cw1(x, [](float a) { return exp2(a); }); }                    \
  inline V log(V x) { return texcc_cw1(x, [](float a) { return log(a); }); }                      \
  inline V log2(V x) { return texcc_cw1(x, [](float a) { return log2(a); }); }                    \
  inline V log10(V x) { return texcc_cw1(x, [](float a) { return log10(a); }); }                  \
  inline V sqrt(V x) { return texcc_cw1(x, [](float a) { return sqrt(a); }); }                    \
  inline V rsqrt(V x) { return texcc_cw1(x, [](float a) { return rsqrt(a); }); }                  \
  inline V fabs(V x) { return texcc_cw1(x, [](float a) { return fabs(a); }); }                    \
  inline V floor(V x) { return texcc_cw1(x, [](float a) { return floor(a); }); }                  \
  inline V ceil(V x) { return texcc_cw1(x, [](float a) { return ceil(a); }); }                    \
  inline V round(V x) { return texcc_cw1(x, [](float a) { return round(a); }); }                  \
  inline V trunc(V x) { return texcc_cw1(x, [](float a) { return trunc(a); }); }                  \
  inline V sign(V x) { return texcc_cw1(x, [](float a) { return sign(a); }); }                    \
  inline V radians(V x) { return texcc_cw1(x, [](float a) { return radians(a); }); }              \
  inline V degrees(V x) { return texcc_cw1(x, [](float a) { return degrees(a); }); }              \
  inline V fract(V x) { return texcc_cw1(x, [](float a) { return fract(a); }); }                  \
  inline V fract(V x, V *ip) {                                                                     \
    *ip = floor(x);                                                                                \
    return texcc_cw1(x, [](float a) { return fract(a); });                                        \
  }                                                                                                \
  inline V pow(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return pow(a, b); }); }  \
  inline V powr(V x, V y) { return pow(x, y); }                                                   \
  inline V fmod(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return fmod(a, b); }); }\
  inline V atan2(V x, V y) {                                                                       \
    return texcc_cw2(x, y, [](float a, float b) { return atan2(a, b); });                         \
  }                                                                                                \
  inline V fmin(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return fmin(a, b); }); }\
  inline V fmax(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return fmax(a, b); }); }\
  inline V fmin(V x, float y) { return fmin(x, V(y)); }                                           \
  inline V fmax(V x, float y) { return fmax(x, V(y)); }                                           \
  inline V min(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return min(a, b); }); }  \
  inline V max(V x, V y) { return texcc_cw2(x, y, [](float a, float b) { return max(a, b); }); }  \
  inline V min(V x, float y) { return min(x, V(y)); }                                             \
  inline V max(V x, float y) { return max(x, V(y)); }                                             \
  inline V step(V e, V x) { return texcc_cw2(e, x, [](float a, float b) { return step(a, b); }); }\
  inline V step(float e, V x) { return step(V(e), x); }                                           \
  inline V clamp(V x, V lo, V hi) {                                                                \
    return texcc_cw3(x, lo, hi, [](float a, float b, float c) { return clamp(a, b, c); });        \
  }                                                                                                \
  inline V clamp(V x, float lo, float hi) { return clamp(x, V(lo), V(hi)); }                      \
  inline V mix(V a, V b, V t) { return a + (b - a) * t; }                                         \
  inline V mix(V a, V b, float t) { return a + (b - a) * t; }                                     \
  inline V mad(V a, V b, V c) { return a * b + c; }                                               \
  inline V fma(V a, V b, V c) {                                                                    \
    return texcc_cw3(a, b, c, [](float x, float y, float z) { return fma(x, y, z); });            \
  }                                                                                                \
  inline V smoothstep(V e0, V e1, V x) {                                                           \
    return texcc_cw3(e0, e1, x, [](float a, float b, float c) { return smoothstep(a, b, c); });   \
  }                                                                                                \
  inline V smoothstep(float e0, float e1, V x) { return smoothstep(V(e0), V(e1), x); }            \
  inline float dot(V a, V b) {                                                                     \
    float S = 0.0f;                                                                                \
    for (int I = 0; I < V::length(); ++I)                                                          \
      S += a[I] * b[I];                                                                            \
    return S;                                                                                      \
  }                                                                                                \
  inline float length(V a) { return std::sqrt(dot(a, a)); }                                      \
  inline float fast_length(V a) { return length(a); }                                             \
  inline float distance(V a, V b) { return length(a - b); }                                       \
  inline V normalize(V a) { return a / length(a); }                                               \
  inline V fast_normalize(V a) { return normalize(a); }
TEXCC_VEC_BUILTINS(float2)
TEXCC_VEC_BUILTINS(float3)
TEXCC_VEC_BUILTINS(float4)
#undef TEXCC_VEC_BUILTINS

inline float3 cross(float3 a, float3 b) {
  return float3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline float4 cross(float4 a, float4 b) {
  return float4(cross(float3(a.x, a.y, a.z), float3(b.x, b.y, b.z)), 0.0f);
}

// native_* and half_* are the full-precision functions here.
#define native_sin sin
#define native_cos cos
#define native_tan tan
#define native_exp exp
#define native_exp2 exp2
#define native_log log
#define native_log2 log2
#define native_sqrt sqrt
#define native_rsqrt rsqrt
#define native_powr powr
#define half_sin sin
#define half_cos cos
#define half_exp exp
#define half_log log
#define half_sqrt sqrt
#define half_rsqrt rsqrt

// ---- integers ----
inline int abs(int x) { return x < 0 ? -x : x; }
inline int min(int x, int y) { return y < x ? y : x; }
inline int max(int x, int y) { return x < y ? y : x; }
inline int clamp(int x, int lo, int hi) { return min(max(x, lo), hi); }
inline uint min(uint x, uint y) { return y < x ? y : x; }
inline uint max(uint x, uint y) { return x < y ? y : x; }

// ---- select: c ? b : a (scalars); vectors take the MSB of each int component ----
inline float select(float a, float b, int c) { return c ? b : a; }
inline int select(int a, int b, int c) { return c ? b : a; }
inline float2 select(float2 a, float2 b, int2 c) {
  return float2(c.x < 0 ? b.x : a.x, c.y < 0 ? b.y : a.y);
}
inline float3 select(float3 a, float3 b, int3 c) {
  return float3(c.x < 0 ? b.x : a.x, c.y < 0 ? b.y : a.y, c.z < 0 ? b.z : a.z);
}
inline float4 select(float4 a, float4 b, int4 c) {
  return float4(c.x < 0 ? b.x : a.x, c.y < 0 ? b.y : a.y, c.z < 0 ? b.z : a.z,
                c.w < 0 ? b.w : a.w);
}

// ---- conversions and reinterpretation ----
inline float convert_float(int x) { return static_cast<float>(x); }
inline int convert_int(float x) { return static_cast<int>(x); }
inline float2 convert_float2(int2 x) { return float2(x); }
inline float3 convert_float3(int3 x) { return float3(x); }
inline float4 convert_float4(int4 x) { return float4(x); }
inline int2 convert_int2(float2 x) { return int2(x); }
inline int3 convert_int3(float3 x) { return int3(x); }
inline int4 convert_int4(float4 x) { return int4(x); }
inline float as_float(uint x) {
  float F;
  std::memcpy(&F, &x, 4);
  return F;
}
inline float as_float(int x) { return as_float(static_cast<uint>(x)); }
inline uint as_uint(float x) {
  uint U;
  std::memcpy(&U, &x, 4);
  return U;
}
inline int as_int(float x) { return static_cast<int>(as_uint(x)); }

// ---- the hit context and the embedded API (kernels/common/texcc_device.h on the device) ----
typedef int sam2D;

#ifndef TEXCC_LOOP_BUDGET
#define TEXCC_LOOP_BUDGET 16777216u
#endif
#ifndef TEXCC_CHECKS
#define TEXCC_CHECKS 1 /* 0: texcc --no-checks (A/B measurement only) */
#endif

// The host target's fault record (texcc_abi.h), exported from the compiled proctex.cpp:
// texcc-eval --host clears it, evaluates, and prints the fault it holds (docs/reliability.md).
extern "C" {
inline int texcc_host_faults[TEXCC_FAULT_WORDS] = {};
}

// The safety state of one evaluation (texcc_device.h); fault null: texcc_host_faults.
struct TexccGuard {
  uint loopsLeft;
  uint at;
  int hit;
  int material;
  int *fault;
  int line;    // of the loop that spent the budget; 0: none did
  uint lineAt; // at, when it did
  int badLine = 0; // of the first __global array read out of bounds (texcc_device.h)
  uint badAt = 0u;
  int badIndex = 0;
  uint badLength = 0u;
  // Its fault, if any, into the record (once). The destructor reports it when the evaluation
  // ends, as texcc_report_fault does at the kernel's end: texcc_host_evaluate keeps its
  // signature.
  void report();
  ~TexccGuard() { report(); }
};

struct TexccCtx {
  TexccHitAttrs hit;
  const TexccSettings *settings;
  const cl_float4 *texels;
  const TexccImageInfo *images;
  TexccGuard *guard;
  // Bump: what WorldPos and ObjectPos add while a height node runs moved (texcc_device.h).
  float3 worldOffset = float3(0.0f);
  float3 objectOffset = float3(0.0f);
};

inline void texcc_guard_fault(const TexccGuard *g, int kind, int line, uint at, int detail,
                              int extra) {
  int *f = g->fault ? g->fault : texcc_host_faults;
  if (f[TEXCC_FAULT_KIND] != TEXCC_FAULT_NONE)
    return;
  f[TEXCC_FAULT_KIND] = kind;
  f[TEXCC_FAULT_LINE] = line;
  f[TEXCC_FAULT_AT] = static_cast<int>(at);
  f[TEXCC_FAULT_HIT] = g->hit;
  f[TEXCC_FAULT_DETAIL] = detail;
  f[TEXCC_FAULT_EXTRA] = extra;
  f[TEXCC_FAULT_MATERIAL] = g->material;
}

inline void texcc_fault(const TexccCtx *c, int kind, int line, uint at, int detail, int extra) {
  texcc_guard_fault(c->guard, kind, line, at, detail, extra);
}

inline bool texcc_loop_continues(const TexccCtx *c, int line) {
  TexccGuard *g = c->guard;
  if (!TEXCC_CHECKS || g->loopsLeft != 0u) {
    --g->loopsLeft;
    return true;
  }
  if (g->line == 0) {
    g->line = line;
    g->lineAt = g->at;
  }
  return false;
}

inline bool texcc_loop_charge(const TexccCtx *c, uint n, int line) {
  TexccGuard *g = c->guard;
  if (!TEXCC_CHECKS || g->loopsLeft >= n) {
    g->loopsLeft -= n;
    return true;
  }
  g->loopsLeft = 0u;
  if (g->line == 0) {
    g->line = line;
    g->lineAt = g->at;
  }
  return false;
}

// A constant `for` charged without a branch before it (texcc_device.h, texcc_loop_charge_once).
inline int texcc_loop_charge_once(const TexccCtx *c, uint n, int line) {
  TexccGuard *g = c->guard;
  const uint left = g->loopsLeft;
  const bool ok = !TEXCC_CHECKS || left >= n;
  g->loopsLeft = ok ? left - n : 0u;
  return ok ? 0 : line;
}

inline void texcc_loop_fault(const TexccCtx *c, int line) {
  TexccGuard *g = c->guard;
  if (g->line == 0) {
    g->line = line;
    g->lineAt = g->at;
  }
}

inline bool texcc_loop_charge_span(const TexccCtx *c, long long span, int line) {
  return texcc_loop_charge(
      c, span <= 0 ? 0u : span >= static_cast<long long>(UINT_MAX) ? UINT_MAX : uint(span), line);
}

inline bool texcc_loop_charge_nest(const TexccCtx *c, long long span, uint per, int line) {
  const unsigned long long n =
      span <= 0 ? 0ull
                : static_cast<unsigned long long>(
                      span < static_cast<long long>(UINT_MAX) ? span : UINT_MAX) * per;
  return texcc_loop_charge(c, n >= UINT_MAX ? UINT_MAX : uint(n), line);
}

inline bool texcc_index_ok(const TexccCtx *c, long long i, uint n, int line) {
  if (!TEXCC_CHECKS || (i >= 0 && static_cast<unsigned long long>(i) < n))
    return true;
  TexccGuard *g = c->guard;
  if (g->badLine == 0) {
    g->badLine = line;
    g->badAt = g->at;
    g->badIndex = static_cast<int>(i < INT_MIN ? INT_MIN : i > INT_MAX ? INT_MAX : i);
    g->badLength = n;
  }
  return false;
}
#define TEXCC_CHECKED_READ(T)                                                                  \
  inline T texcc_read_##T(const TexccCtx *c, const T *p, long long i, uint n, int line) {     \
    return texcc_index_ok(c, i, n, line) ? p[i] : T(0);                                        \
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
// A private array's subscript that texcc cannot prove in range (texcc_device.h).
inline long long texcc_index(const TexccCtx *c, long long i, uint n, int line) {
  return texcc_index_ok(c, i, n, line) ? i : 0;
}

// A loop past its budget first: its out-of-range reads may be a consequence.
inline void TexccGuard::report() {
  if (TEXCC_CHECKS && line != 0)
    texcc_guard_fault(this, TEXCC_FAULT_LOOP_BUDGET, line, lineAt,
                      static_cast<int>(TEXCC_LOOP_BUDGET), 0);
  else if (TEXCC_CHECKS && badLine != 0)
    texcc_guard_fault(this, TEXCC_FAULT_INDEX, badLine, badAt, badIndex,
                      static_cast<int>(badLength));
  line = badLine = 0;
}

inline void texcc_report_fault(const TexccCtx *c) { c->guard->report(); }

#define TEXCC_CTX_PARAM const TexccCtx *texcc_ctx
#define TEXCC_CTX_ARG texcc_ctx
#define TEXCC_FN

inline float4 texcc_f4(const cl_float4 &v) { return float4(v.s[0], v.s[1], v.s[2], v.s[3]); }
inline float3 texcc_f3(const cl_float4 &v) { return float3(v.s[0], v.s[1], v.s[2]); }

inline float3 texcc_attr_WorldPos(const TexccCtx *c) {
  return texcc_f3(c->hit.worldPos) + c->worldOffset;
}
inline float3 texcc_attr_ObjectPos(const TexccCtx *c) {
  return texcc_f3(c->hit.objectPos) + c->objectOffset;
}
inline float3 texcc_attr_Normal(const TexccCtx *c) { return texcc_f3(c->hit.normal); }
inline float3 texcc_attr_GeomNormal(const TexccCtx *c) { return texcc_f3(c->hit.geomNormal); }
inline float3 texcc_attr_Tangent(const TexccCtx *c) { return texcc_f3(c->hit.tangent); }
inline float2 texcc_attr_TexCoord0(const TexccCtx *c) {
  return float2(c->hit.uvAO.s[0], c->hit.uvAO.s[1]);
}
inline float texcc_attr_AO(const TexccCtx *c) { return c->hit.uvAO.s[2]; }
inline float3 texcc_attr_ViewDir(const TexccCtx *c) { return texcc_f3(c->hit.viewDir); }
inline float texcc_attr_TangentSign(const TexccCtx *c) { return c->hit.tangent.s[3]; }
inline float texcc_attr_Backfacing(const TexccCtx *c) { return c->hit.uvAO.s[3]; }

inline float texcc_setting_Time(const TexccCtx *c) { return c->settings->time; }
inline int texcc_setting_Frame(const TexccCtx *c) { return c->settings->frame; }
inline float3 texcc_setting_CameraPos(const TexccCtx *c) {
  return texcc_f3(c->settings->cameraPos);
}

// Bump: as texcc_device.h's texcc_bump_footprint, texcc_bump_step, texcc_bump_frame,
// texcc_position_offset and texcc_bump (the same operations in the same order).
#ifndef TEXCC_BUMP_FILTER_WIDTH
#define TEXCC_BUMP_FILTER_WIDTH 0.1f
#endif
inline float texcc_bump_footprint(const TexccCtx *c) {
  const float3 v = texcc_f3(c->hit.worldPos) - texcc_f3(c->settings->cameraPos);
  const float z = dot(v, texcc_f3(c->settings->cameraForward));
  float f = 1.0f;
  if (z > 0.0f) {
    const float x = dot(v, texcc_f3(c->settings->cameraRight)) / z;
    const float y = dot(v, texcc_f3(c->settings->cameraUp)) / z;
    f = 0.5f * (sqrt(1.0f + y * y) + sqrt(1.0f + x * x)) / (1.0f + x * x + y * y);
  }
  return c->settings->pixelAngle * length(v) * f;
}
inline float texcc_bump_step(const TexccCtx *c) {
  const float3 a = fabs(texcc_f3(c->hit.worldPos));
  return fmax(TEXCC_BUMP_FILTER_WIDTH * texcc_bump_footprint(c),
              1e-4f * (1.0f + fmax(a.x, fmax(a.y, a.z))));
}
inline float3 texcc_bump_frame(const TexccCtx *c, float3 *b) {
  float3 n = texcc_f3(c->hit.geomNormal);
  if (!(dot(n, n) > 0.25f))
    n = texcc_f3(c->hit.normal);
  const float3 a = normalize((n.x != n.y || n.x != n.z)
                                 ? float3(n.z - n.y, n.x - n.z, n.y - n.x)
                                 : float3(n.z - n.y, n.x + n.z, -n.y - n.x));
  *b = cross(n, a);
  return a;
}
inline void texcc_position_offset(const TexccCtx *c, int k) {
  TexccCtx *m = const_cast<TexccCtx *>(c);
  m->worldOffset = m->objectOffset = float3(0.0f);
  if (k == 0)
    return;
  const float e = texcc_bump_step(c);
  float3 b;
  const float3 a = texcc_bump_frame(c, &b);
  m->worldOffset = e * (k == 1 ? a : b);
  m->objectOffset =
      e * (k == 1 ? texcc_f3(c->hit.objectTangent) : texcc_f3(c->hit.objectBitangent));
}
inline float3 texcc_bump(const TexccCtx *c, float h, float strength, float distance,
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

inline float4 texcc_texel(const cl_float4 *texels, TexccImageInfo im, int x, int y) {
  x = x % im.width;
  if (x < 0)
    x += im.width;
  y = y % im.height;
  if (y < 0)
    y += im.height;
  return texcc_f4(texels[im.offset + y * im.width + x]);
}

inline float4 texcc_tex2D(const TexccCtx *c, sam2D s, float2 uv) {
  if (s < 0)
    return float4(1.0f, 0.0f, 1.0f, 1.0f);
  TexccImageInfo im = c->images[s];
  if (im.width <= 0 || im.height <= 0)
    return float4(1.0f, 0.0f, 1.0f, 1.0f);
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

// texcc_tex2DFiltered: kernels/common/texcc_device.h's, in scalar code.
inline int texcc_extend(int x, int n, int extension) {
  if (extension == 1)
    return x < 0 ? 0 : x > n - 1 ? n - 1 : x;
  if (extension == 2)
    return x < 0 || x >= n ? -1 : x;
  if (extension == 3) {
    const int m = std::abs(x + (x < 0 ? 1 : 0)) % (2 * n);
    return m >= n ? 2 * n - m - 1 : m;
  }
  x = x % n;
  return x < 0 ? x + n : x;
}

inline float4 texcc_texel_filtered(const cl_float4 *texels, TexccImageInfo im, int x, int y) {
  if (x < 0 || y < 0)
    return float4(0.0f);
  float4 t = texcc_f4(texels[im.offset + y * im.width + x]);
  for (int k = 0; k < 3; ++k) {
    float v = t[k];
    if (im.flags & TEXCC_IMAGE_SRGB) {
      v = v < 0.0f ? 0.0f : v;
      v = v < 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    }
    const float m = (im.flags & TEXCC_IMAGE_BYTES) ? 255.0f : 65535.0f;
    if (!(im.flags & TEXCC_IMAGE_DATA) && t[3] != 1.0f)
      v = (im.flags & (TEXCC_IMAGE_BYTES | TEXCC_IMAGE_SHORTS))
              ? std::floor(std::nearbyint(v * m) * std::nearbyint(t[3] * m) / m) / m
              : v * t[3];
    t[k] = v;
  }
  return t;
}

inline float4 texcc_bspline(float t) {
  const float s = 1.0f - t;
  return float4(s * s * s, 3.0f * t * t * t - 6.0f * t * t + 4.0f,
                -3.0f * t * t * t + 3.0f * t * t + 3.0f * t + 1.0f, t * t * t) / 6.0f;
}

inline float4 texcc_tex2DFiltered(const TexccCtx *c, sam2D s, float2 uv, int interpolation,
                                  int extension, int straight) {
  if (s < 0)
    return float4(1.0f, 0.0f, 1.0f, 1.0f);
  TexccImageInfo im = c->images[s];
  if (im.width <= 0 || im.height <= 0)
    return float4(1.0f, 0.0f, 1.0f, 1.0f);
  float4 r(0.0f);
  if (interpolation == 1) {
    const int x = texcc_extend((int)std::floor(uv.x * (float)im.width), im.width, extension);
    const int y = texcc_extend((int)std::floor(uv.y * (float)im.height), im.height, extension);
    r = texcc_texel_filtered(c->texels, im, x, y);
  } else {
    const float fx = uv.x * (float)im.width - 0.5f, fy = uv.y * (float)im.height - 0.5f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = (int)x0f, y0 = (int)y0f;
    if (interpolation == 2) {
      const float4 wx = texcc_bspline(tx), wy = texcc_bspline(ty);
      for (int j = 0; j < 4; ++j) {
        const int y = texcc_extend(y0 - 1 + j, im.height, extension);
        float4 row(0.0f);
        for (int i = 0; i < 4; ++i)
          row += wx[i] * texcc_texel_filtered(c->texels, im,
                                              texcc_extend(x0 - 1 + i, im.width, extension), y);
        r += wy[j] * row;
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
  if (straight && !(im.flags & TEXCC_IMAGE_DATA) && r[3] != 0.0f && r[3] != 1.0f)
    for (int k = 0; k < 3; ++k)
      r[k] /= r[3];
  if (im.flags & TEXCC_IMAGE_SRGB)
    for (int k = 0; k < 3; ++k) {
      const float v = r[k];
      r[k] = v < 0.0f ? 0.0f : v < 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    }
  return r;
}

} // namespace texcc_cl

#endif
