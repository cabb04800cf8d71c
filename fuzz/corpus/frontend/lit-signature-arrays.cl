// __global const T* parameters (T float..float4, int) and sam2D are texture parameter types.
// RUN: texcc-fe %s --texture ramp | FileCheck %s

float4 ramp(float t, __global const float4 *stops, __global const float *weights, __global const int *ids, sam2D img, const int count) {
  return stops[0] * weights[0] + ids[0] + img + count + t;
}
// CHECK-LABEL: // texcc-fe signatures:
// CHECK: "type": "float"
// CHECK: "type": "__global const float4*"
// CHECK: "type": "__global const float*"
// CHECK: "type": "__global const int*"
// CHECK: "type": "sam2D"
// CHECK: "name": "count",
// CHECK-NEXT: "type": "int"
// CHECK: "return": "float4",
