// f() becomes f(TEXCC_CTX_PARAM).
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float ctx_param_empty_one(TEXCC_CTX_PARAM) { return 1.0f; }
float one() { return 1.0f; }
