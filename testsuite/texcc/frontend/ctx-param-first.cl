// A function with parameters gets TEXCC_CTX_PARAM inserted before the first one.
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float2 ctx_param_first_f(TEXCC_CTX_PARAM, float a, int b) { return (float2)(a, b); }
float2 f(float a, int b) { return (float2)(a, b); }
