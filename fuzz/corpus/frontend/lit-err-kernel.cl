// Texture files hold functions only; texcc generates the kernel.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

// CHECK: err-kernel.cl:[[@LINE+1]]:15: error: texture files may not define kernels ('main'); texcc generates the kernel
__kernel void main(__global const float *in) {}
