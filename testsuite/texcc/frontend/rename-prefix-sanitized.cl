// The prefix is the file stem made an identifier: 'rename-prefix-sanitized.cl' gives
// 'rename_prefix_sanitized_'.
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float rename_prefix_sanitized_f(TEXCC_CTX_PARAM, float x) { return x; }
float f(float x) { return x; }
