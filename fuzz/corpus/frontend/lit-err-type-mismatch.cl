// readAttr("Normal") is a float3: Clang reports a mismatch at the user's own line.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(void) {
  // CHECK: err-type-mismatch.cl:[[@LINE+1]]:10: error: initializing '__private float2' (vector of 2 'float' values) with an expression of incompatible type 'float3'
  float2 n = readAttr("Normal");
  return n.x;
}
