// A -D macro is defined before the file's section and #undef'd after it, so that the kernel sees
// what the front end saw.
// RUN: texcc-fe %s -D OCTAVES=4 -D FAST | FileCheck %s

// CHECK: {{^}}#define OCTAVES 4
// CHECK-NEXT: {{^}}#define FAST 1
// CHECK-NEXT: {{^}}#line 1
float f(void) { return OCTAVES * FAST; }
// CHECK: {{^}}#undef OCTAVES
// CHECK-NEXT: {{^}}#undef FAST
