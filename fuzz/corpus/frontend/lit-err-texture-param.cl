// A texture parameter must be float..float4, int, sam2D or __global const T*.
// RUN: not texcc-fe %s --texture tex 2>&1 | FileCheck %s

// CHECK: err-texture-param.cl:[[@LINE+2]]:23: error: parameter 'weights' of texture 'tex' has unsupported type '__global float *'; allowed: float, float2, float3, float4, int, sam2D, __global const T* (T: float, float2, float3, float4, int)
// CHECK: err-texture-param.cl:[[@LINE+1]]:48: error: parameter 'b' of texture 'tex' has unsupported type 'uchar'
float tex(float x,    __global float *weights, uchar b) { return x + weights[0] + b; }
