// An unknown attribute name is an error at the argument, listing the allowed names.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(void) {
  // CHECK: err-unknown-attribute.cl:[[@LINE+1]]:26: error: unknown attribute 'Bogus'; expected one of AO, Backfacing, GeomNormal, Normal, ObjectPos, Tangent, TangentSign, TexCoord0, ViewDir, WorldPos
  return 1.0f + readAttr("Bogus");
}
