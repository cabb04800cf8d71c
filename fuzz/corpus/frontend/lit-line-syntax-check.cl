// The rendered code, pasted after texcc_abi.h and texcc_device.h as proctex.cl does, passes
// clang -x cl -cl-std=CL1.2 -fsyntax-only (every lowering and the threaded context included).
// RUN: texcc-fe %s --texture shade > %t.cl
// RUN: sh %inputs/frontend/syntax-check.sh %clang %t.cl

#define GAIN 2.0f
float helper(void) { return readSetting("Time") * GAIN; }
float3 bend(float3 n) { return n * helper(); }
float4 shade(sam2D img, __global const float4 *stops, int count, float3 p) {
  float3 n = bend(readAttr("Normal")) + readAttr("WorldPos") + readAttr("ObjectPos");
  float3 more = readAttr("GeomNormal") + readAttr("Tangent") + readAttr("ViewDir") + readSetting("CameraPos");
  float4 c = tex2D(img, readAttr("TexCoord0")) * readAttr("AO");
  int frame = readSetting("Frame");
  return c + stops[count - 1] + (float4)(n + more + p, (float)frame);
}
