// A call without arguments passes TEXCC_CTX_ARG alone.
// RUN: texcc-fe %s | FileCheck %s

float one(void) { return 1.0f; }
// CHECK: {{^}}TEXCC_FN float ctx_arg_noargs_two(TEXCC_CTX_PARAM) { return ctx_arg_noargs_one(TEXCC_CTX_ARG) + ctx_arg_noargs_one(TEXCC_CTX_ARG); }
float two(void) { return one() + one(); }
