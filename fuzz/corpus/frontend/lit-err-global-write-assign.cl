// Assigning through a __global pointer is rejected.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(__global float *values, int i) {
  // CHECK: err-global-write-assign.cl:[[@LINE+1]]:3: error: cannot write through __global pointer 'values': __global memory is read-only in texture code
  values[i] = 1.0f;
  return values[0];
}
