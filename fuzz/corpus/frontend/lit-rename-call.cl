// A call to a user function is renamed and passes the hit context first.
// RUN: texcc-fe %s | FileCheck %s

float helper(float x) { return x + 1.0f; }
float caller(float x) {
  // CHECK: {{^}}  return rename_call_helper(TEXCC_CTX_ARG, x) * rename_call_helper(TEXCC_CTX_ARG, 2.0f);
  return helper(x) * helper(2.0f);
}
