// readAttr("N") lowers to texcc_attr_N(texcc_ctx), with the type of the attribute.
// RUN: texcc-fe %s | FileCheck %s

float3 f(void) {
  // CHECK: {{^}}  float3 n = texcc_attr_Normal(texcc_ctx);
  float3 n = readAttr("Normal");
  // CHECK: {{^}}  float2 uv = texcc_attr_TexCoord0(texcc_ctx);
  float2 uv = readAttr("TexCoord0");
  // CHECK: {{^}}  float ao = texcc_attr_AO(texcc_ctx);
  float ao = readAttr("AO");
  // CHECK: {{^}}  return n + texcc_attr_WorldPos(texcc_ctx) + texcc_attr_ObjectPos(texcc_ctx) + texcc_attr_GeomNormal(texcc_ctx) + texcc_attr_Tangent(texcc_ctx) + texcc_attr_ViewDir(texcc_ctx) + uv.x + ao;
  return n + readAttr("WorldPos") + readAttr("ObjectPos") + readAttr("GeomNormal") + readAttr("Tangent") + readAttr("ViewDir") + uv.x + ao;
}
