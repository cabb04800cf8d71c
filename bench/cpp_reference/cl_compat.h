/* cl_compat.h: the OpenCL C builtins that the texture files and texcc's generated proctex.cl
 * use, defined for clang's OpenCL C front end on the host CPU (clang-15 -x cl -cl-std=CL1.2
 * -finclude-default-header --target=x86_64-linux-gnu: opencl-c.h declares every builtin, this
 * file defines those that are called), so that
 * textures/blender/ files and userfbm.cl compile unchanged into native code for the C reference
 * (bench/cpp_reference/README.md). clang's OpenCL mode gives the vector types, vector literals,
 * swizzles and as_T reinterpretations; the math builtins below are the C library's (libm:
 * correctly rounded floor/fabs/fmod/sqrt, and sinf/powf as glibc computes them), component by
 * component on vectors. No fast math: the file is built with -ffp-contract=off as texcc's
 * kernels are (FP_CONTRACT OFF). */
#ifndef CL_COMPAT_H
#define CL_COMPAT_H

#define OVL __attribute__((overloadable, always_inline))




OVL float floor(float x) { return __builtin_floorf(x); }
OVL float ceil(float x) { return __builtin_ceilf(x); }
OVL float fabs(float x) { return __builtin_fabsf(x); }
OVL float sqrt(float x) { return __builtin_sqrtf(x); }
OVL float fmod(float x, float y) { return __builtin_fmodf(x, y); }
OVL float pow(float x, float y) { return __builtin_powf(x, y); }
OVL float sin(float x) { return __builtin_sinf(x); }
OVL float cos(float x) { return __builtin_cosf(x); }
OVL float fma(float a, float b, float c) { return __builtin_fmaf(a, b, c); }
/* OpenCL's fmax/fmin: the other operand when one is NaN, as C's. */
OVL float fmax(float x, float y) { return __builtin_fmaxf(x, y); }
OVL float fmin(float x, float y) { return __builtin_fminf(x, y); }
OVL float clamp(float x, float lo, float hi) { return fmin(fmax(x, lo), hi); }
OVL float mix(float a, float b, float t) { return a + (b - a) * t; }
OVL int min(int a, int b) { return a < b ? a : b; }
OVL int max(int a, int b) { return a > b ? a : b; }
OVL int clamp(int x, int lo, int hi) { return min(max(x, lo), hi); }
OVL long min(long a, long b) { return a < b ? a : b; }
OVL long max(long a, long b) { return a > b ? a : b; }
OVL long clamp(long x, long lo, long hi) { return min(max(x, lo), hi); }
OVL uint min(uint a, uint b) { return a < b ? a : b; }
OVL uint max(uint a, uint b) { return a > b ? a : b; }
OVL ulong min(ulong a, ulong b) { return a < b ? a : b; }
OVL ulong max(ulong a, ulong b) { return a > b ? a : b; }
OVL uint abs(int x) { return (uint)(x < 0 ? -x : x); }

#define CLC_MAP1(V, N, F)                                                                      \
  OVL V F(V x) {                                                                               \
    V r;                                                                                       \
    for (int i = 0; i < N; ++i) r[i] = F(x[i]);                                                \
    return r;                                                                                  \
  }
#define CLC_MAP2(V, N, F)                                                                      \
  OVL V F(V x, V y) {                                                                          \
    V r;                                                                                       \
    for (int i = 0; i < N; ++i) r[i] = F(x[i], y[i]);                                          \
    return r;                                                                                  \
  }
#define CLC_VEC(V, N)                                                                          \
  CLC_MAP1(V, N, floor) CLC_MAP1(V, N, ceil) CLC_MAP1(V, N, fabs) CLC_MAP1(V, N, sqrt)        \
  CLC_MAP1(V, N, sin) CLC_MAP1(V, N, cos) CLC_MAP2(V, N, fmax) CLC_MAP2(V, N, fmin)           \
  CLC_MAP2(V, N, fmod) CLC_MAP2(V, N, pow)                                                     \
  OVL V fmax(V x, float y) { return fmax(x, (V)(y)); }                                         \
  OVL V fmin(V x, float y) { return fmin(x, (V)(y)); }                                         \
  OVL V clamp(V x, V lo, V hi) { return fmin(fmax(x, lo), hi); }                               \
  OVL V clamp(V x, float lo, float hi) { return fmin(fmax(x, (V)(lo)), (V)(hi)); }             \
  OVL V mix(V a, V b, V t) { return a + (b - a) * t; }                                         \
  OVL V mix(V a, V b, float t) { return a + (b - a) * t; }
CLC_VEC(float2, 2)
CLC_VEC(float3, 3)
CLC_VEC(float4, 4)

/* OpenCL's convert_T (round toward zero for float to int, as a C cast) for 3-vectors. */
OVL float3 convert_float3(uint3 v) { return __builtin_convertvector(v, float3); }
OVL float3 convert_float3(int3 v) { return __builtin_convertvector(v, float3); }
OVL int3 convert_int3(float3 v) { return __builtin_convertvector(v, int3); }
OVL int2 convert_int2(float2 v) { return __builtin_convertvector(v, int2); }
OVL int4 convert_int4(float4 v) { return __builtin_convertvector(v, int4); }
OVL float4 convert_float4(int4 v) { return __builtin_convertvector(v, float4); }

/* OpenCL's select on vectors: b in the lanes whose mask has its top bit set, a elsewhere (the
 * Blender library's Perlin and Voronoi code on uint4 masks). */
OVL float4 select(float4 a, float4 b, uint4 c) { return as_int4(c) < 0 ? b : a; }
OVL float4 select(float4 a, float4 b, int4 c) { return c < 0 ? b : a; }
OVL float3 select(float3 a, float3 b, int3 c) { return c < 0 ? b : a; }


/* What the kernel of proctex.cl calls besides the math: one work-item at a time, on one thread
 * (bench/cpp_reference/proctex_host.c sets the id before each call). */
size_t clcGlobalId(void); /* defined in C by the caller */
OVL size_t get_global_id(uint d) { return d == 0 ? clcGlobalId() : 0; }
OVL int atomic_cmpxchg(volatile __global int *p, int cmp, int val) {
  int old = *p;
  if (old == cmp) *p = val;
  return old;
}

#endif
