// A loop whose head a user macro spells is bounded inside the macro's body (every expansion
// is bounded; __LINE__ is the expansion's line).
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}#define REPEAT(k, n) for (int k = 0; (k < (n)) && texcc_loop_continues(texcc_ctx, __LINE__); ++k)
#define REPEAT(k, n) for (int k = 0; k < (n); ++k)
float f(int n) {
  float s = 0.0f;
  REPEAT(i, n) s += 1.0f;
  REPEAT(j, 3) s *= 0.5f;
  return s;
}
