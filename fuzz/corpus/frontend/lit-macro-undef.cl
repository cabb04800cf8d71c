// Every macro the file defines is #undef'd after its section (hygiene), in definition order.
// RUN: texcc-fe %s | FileCheck %s

#define GAIN 2.0f
#define TWICE(x) ((x) * GAIN)
float f(float x) { return TWICE(x); }
// CHECK: {{^}}#undef GAIN
// CHECK-NEXT: {{^}}#undef TWICE
// CHECK-NEXT: // texcc-fe signatures:
