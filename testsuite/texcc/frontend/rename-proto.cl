// A prototype is renamed like its definition.
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float rename_proto_later(TEXCC_CTX_PARAM, float x);
float later(float x);
float first(float x) { return later(x); }
// CHECK: {{^}}TEXCC_FN float rename_proto_later(TEXCC_CTX_PARAM, float x) { return x; }
float later(float x) { return x; }
