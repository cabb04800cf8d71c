// A compound assignment through a __global pointer is rejected.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(__global float4 *colors) {
  // CHECK: err-global-write-compound.cl:[[@LINE+1]]:3: error: cannot write through __global pointer 'colors'
  colors[1].x *= 2.0f;
  return colors[1].x;
}
