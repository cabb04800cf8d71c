// tex2D(s, uv) lowers to texcc_tex2D(texcc_ctx, s, uv); sam2D stays (a typedef of int in
// texcc_device.h).
// RUN: texcc-fe %s | FileCheck %s

float4 img(sam2D s, float2 uv) {
  return tex2D(s, uv * 2.0f);
}
// CHECK: {{^}}TEXCC_FN float4 lower_tex2d_img(TEXCC_CTX_PARAM, sam2D s, float2 uv) {
// CHECK-NEXT: {{^}}  return texcc_tex2D(texcc_ctx, s, uv * 2.0f);
