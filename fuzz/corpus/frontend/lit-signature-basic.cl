// The signature of a requested texture: parameter names and types, return type, renamed name.
// RUN: texcc-fe %s --texture fbm3 | FileCheck %s

float fbm3(float3 p, float scale, int octaves, float2 offset, float4 tint) { return p.x * scale + octaves; }
// CHECK-LABEL: // texcc-fe signatures:
// CHECK: "fbm3": {
// CHECK: "file": "{{.*}}signature-basic.cl"
// CHECK: "name": "p",
// CHECK-NEXT: "type": "float3"
// CHECK: "name": "scale",
// CHECK-NEXT: "type": "float"
// CHECK: "name": "octaves",
// CHECK-NEXT: "type": "int"
// CHECK: "name": "offset",
// CHECK-NEXT: "type": "float2"
// CHECK: "name": "tint",
// CHECK-NEXT: "type": "float4"
// CHECK: "renamed": "signature_basic_fbm3",
// CHECK-NEXT: "return": "float",
