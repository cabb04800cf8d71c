/* Hand-written stand-in for texcc's interp output on graph.json (docs/abi.md), for the
 * runtime's tests until they run on texcc's own kernels: a real interpreter of the fake stack
 * (programs, argument records, constant/slot/attribute sources) with one function, tint. */
#include "texcc_abi.h"
#include "texcc_device.h"

#define TEXCC_STACK_SLOTS 1
#define TEXCC_MAX_OUTPUTS 1
#define TEXCC_NUM_MATERIALS 2
#define TEXCC_SPILL 0

__constant uint texcc_program_offset[TEXCC_NUM_MATERIALS] = {0, 6};

#line 3 "tint.cl"
float3 tint_tint(TEXCC_CTX_PARAM, float3 color, float gain) { return color * gain; }
#line 18 "proctex.cl"

/* Argument p of the record at byte offset rec: a constant from the parameter block, a stack
 * slot, or an attribute, widened to float4. */
float4 texcc_arg(const TexccCtx *ctx, __global const uint *fs, uint rec, uint numParams, uint p,
                 uint blockOffset, uint components, float4 *stack) {
  uint src = fs[rec / 4 + p];
  uint kind = src >> 30, index = src & 0xFFFFu;
  float4 v = (float4)(0.0f);
  if (kind == 1u) {
    v = stack[index];
  } else if (kind == 2u) {
    v = texcc_attr_by_id(ctx, index);
  } else {
    uint block = rec + ((numParams * 4u + 15u) & ~15u) + blockOffset;
    __global const float *f = (__global const float *)(fs + block / 4);
    for (uint c = 0; c < components; ++c)
      ((float *)&v)[c] = f[c];
    return v;
  }
  if (src & (1u << 29))
    v = (float4)(v.x);
  return v;
}

__kernel void texcc_proctex(__global const TexccHitAttrs *hits, __global const int *hitMaterial,
                            int numHits, __global const uint *fakeStack,
                            __global const TexccSettings *settings,
                            __global const float4 *texels, __global const TexccImageInfo *images,
                            __global float4 *outputs, __global float4 *scratch) {
  int gid = get_global_id(0);
  if (gid >= numHits)
    return;
  int m = hitMaterial[gid];
  if (m < 0 || m >= TEXCC_NUM_MATERIALS)
    return;
  TexccCtx ctx;
  ctx.hit = hits[gid];
  ctx.settings = settings;
  ctx.texels = texels;
  ctx.images = images;
  float4 stack[TEXCC_STACK_SLOTS];
  __global const uint *prog = fakeStack + texcc_program_offset[m];
  uint n = prog[0], nout = prog[1];
  for (uint i = 0; i < n; ++i) {
    uint fn = prog[2 + 3 * i], slot = prog[3 + 3 * i], rec = prog[4 + 3 * i];
    switch (fn) {
    case 0: {
      float4 color = texcc_arg(&ctx, fakeStack, rec, 2, 0, 0, 3, stack);
      float4 gain = texcc_arg(&ctx, fakeStack, rec, 2, 1, 16, 1, stack);
      stack[slot] = (float4)(tint_tint(&ctx, color.xyz, gain.x), 0.0f);
      break;
    }
    default:
      stack[slot] = (float4)(1.0f, 0.0f, 1.0f, 0.0f);
    }
  }
  for (uint k = 0; k < nout; ++k)
    outputs[gid * TEXCC_MAX_OUTPUTS + k] = stack[prog[2 + 3 * n + k]];
}
