// OpenCL builtins (declared lazily by Clang at first use) are never renamed or threaded.
// RUN: texcc-fe %s | FileCheck %s

float user(float3 p) {
  // CHECK: {{^}}  return sin(p.x) + dot(p, p) + clamp(p.y, 0.0f, 1.0f) + mix(1.0f, 2.0f, p.z);
  return sin(p.x) + dot(p, p) + clamp(p.y, 0.0f, 1.0f) + mix(1.0f, 2.0f, p.z);
}
