// Writing through *p where p points to __global is rejected.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(__global float *p) {
  // CHECK: err-global-write-deref.cl:[[@LINE+1]]:3: error: cannot write through __global pointer 'p'
  *p = 0.0f;
  return *p;
}
