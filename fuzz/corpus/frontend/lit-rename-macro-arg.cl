// A call spelled in a macro argument is renamed where it is spelled.
// RUN: texcc-fe %s | FileCheck %s

#define SQUARE(v) ((v) * (v))
float helper(float x) { return x + 1.0f; }
float user(float x) {
  // CHECK: {{^}}  return SQUARE(rename_macro_arg_helper(TEXCC_CTX_ARG, x));
  return SQUARE(helper(x));
}
