// double needs fp64, which texture code does not have.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(float x) {
  // CHECK: err-double.cl:[[@LINE+1]]:3: error: use of type 'double' requires cl_khr_fp64 support
  double y = x;
  return (float)y;
}
