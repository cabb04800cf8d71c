// Helpers (functions no graph node names) may use any type; only textures are restricted.
// RUN: texcc-fe %s --texture tex | FileCheck %s

uint mixBits(uint a, uchar b) { return a ^ b; }
// CHECK: "tex": {
float tex(float x) { return (float)mixBits((uint)x, 3); }
