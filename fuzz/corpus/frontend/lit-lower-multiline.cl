// A call split over lines is lowered without shifting the lines after it.
// RUN: texcc-fe %s | FileCheck %s

float f(void) {
  float ao = readAttr(
      "AO");
  return ao;
}
// CHECK: {{^}}  float ao = texcc_attr_AO(texcc_ctx){{$}}
// CHECK-NEXT: {{^}};{{$}}
// CHECK-NEXT: {{^}}  return ao;
