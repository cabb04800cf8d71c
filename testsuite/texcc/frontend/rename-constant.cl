// Program-scope variables (__constant tables) are renamed like functions, so that two files
// may both define one.
// RUN: texcc-fe %s | FileCheck %s

__constant float kWeights[2] = {0.25f, 0.75f};
float blend(float a, float b) { return a * kWeights[0] + b * kWeights[1]; }
// CHECK: {{^}}__constant float rename_constant_kWeights[2] = {0.25f, 0.75f};
// CHECK-NEXT: {{^}}TEXCC_FN float rename_constant_blend(TEXCC_CTX_PARAM, float a, float b) { return a * rename_constant_kWeights[0] + b * rename_constant_kWeights[1]; }
