// A call spelled inside a user macro's body is renamed in the body, once however often the
// macro is used.
// RUN: texcc-fe %s | FileCheck %s

float helper(float x) { return x + 1.0f; }
// CHECK: {{^}}#define TWICE(x) (rename_macro_body_helper(TEXCC_CTX_ARG, x) * 2.0f)
#define TWICE(x) (helper(x) * 2.0f)
// CHECK: {{^}}TEXCC_FN float rename_macro_body_user(TEXCC_CTX_PARAM, float x) { return TWICE(x) + TWICE(x + 1.0f); }
float user(float x) { return TWICE(x) + TWICE(x + 1.0f); }
