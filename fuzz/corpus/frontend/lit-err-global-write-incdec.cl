// ++ and -- through a __global pointer are rejected.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

int f(__global int *counts) {
  // CHECK: err-global-write-incdec.cl:[[@LINE+1]]:3: error: cannot write through __global pointer 'counts'
  counts[0]++;
  // CHECK: err-global-write-incdec.cl:[[@LINE+1]]:5: error: cannot write through __global pointer 'counts'
  --counts[1];
  return counts[0];
}
