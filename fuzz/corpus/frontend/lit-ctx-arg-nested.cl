// Nested calls each get the context, also in arguments of builtins.
// RUN: texcc-fe %s | FileCheck %s

float inc(float x) { return x + 1.0f; }
float f(float x) {
  // CHECK: {{^}}  return sin(ctx_arg_nested_inc(TEXCC_CTX_ARG, ctx_arg_nested_inc(TEXCC_CTX_ARG, x)));
  return sin(inc(inc(x)));
}
