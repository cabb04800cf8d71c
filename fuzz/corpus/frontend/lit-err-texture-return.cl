// A texture must return float..float4; the error names the allowed types.
// RUN: not texcc-fe %s --texture count 2>&1 | FileCheck %s

// CHECK: err-texture-return.cl:[[@LINE+1]]:1: error: texture 'count' returns unsupported type 'int'; a texture returns float, float2, float3 or float4
int count(float x) { return (int)x; }
