/* A texture kernel that does not compile: the error is in the user's tint.cl (line 4, as the
 * #line below says), and texrender's build-failure message must point there. */
#include "texcc_abi.h"
#include "texcc_device.h"

#line 3 "tint.cl"
float3 tint_tint(TEXCC_CTX_PARAM, float3 color, float gain) {
  return color * undefined_gain;
}
#line 12 "proctex.cl"

__kernel void texcc_proctex(__global const TexccHitAttrs *hits, __global const int *hitMaterial,
                            int numHits, __global const uint *fakeStack,
                            __global const TexccSettings *settings,
                            __global const float4 *texels, __global const TexccImageInfo *images,
                            __global float4 *outputs, __global float4 *scratch) {
}
