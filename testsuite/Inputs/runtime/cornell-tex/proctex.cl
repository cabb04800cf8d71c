/* Hand-written stand-in for texcc's output on examples/cornell/graph.json (docs/abi.md): three
 * constant materials, so no material has texture outputs and the kernel does nothing. */
#include "texcc_abi.h"
#include "texcc_device.h"

#define TEXCC_STACK_SLOTS 1
#define TEXCC_MAX_OUTPUTS 1
#define TEXCC_NUM_MATERIALS 3
#define TEXCC_SPILL 0

__kernel void texcc_proctex(__global const TexccHitAttrs *hits, __global const int *hitMaterial,
                            int numHits, __global const uint *fakeStack,
                            __global const TexccSettings *settings,
                            __global const float4 *texels, __global const TexccImageInfo *images,
                            __global float4 *outputs, __global float4 *scratch) {
}
