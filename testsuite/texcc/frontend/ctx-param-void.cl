// f(void) becomes f(TEXCC_CTX_PARAM).
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float ctx_param_void_one(TEXCC_CTX_PARAM) { return 1.0f; }
float one(void) { return 1.0f; }
