// A texture's attributes and settings are those read by its whole call tree, sorted; its
// reachable functions are listed by renamed name.
// RUN: texcc-fe %s --texture top --texture alone | FileCheck %s

float leaf(void) { return readAttr("AO") + readSetting("Time"); }
float mid(void) { return leaf() + readAttr("Normal").x; }
float top(float3 p) { return mid() + readAttr("ObjectPos").x; }
float alone(float x) { return x; }
// CHECK-LABEL: // texcc-fe signatures:
// CHECK: "alone": {
// CHECK-NEXT: "attributes": [],
// CHECK: "reachable": [
// CHECK-NEXT: "signature_calltree_alone"
// CHECK-NEXT: ],
// CHECK: "settings": []
// CHECK: "top": {
// CHECK-NEXT: "attributes": [
// CHECK-NEXT: "AO",
// CHECK-NEXT: "Normal",
// CHECK-NEXT: "ObjectPos"
// CHECK-NEXT: ],
// CHECK: "reachable": [
// CHECK-NEXT: "signature_calltree_leaf",
// CHECK-NEXT: "signature_calltree_mid",
// CHECK-NEXT: "signature_calltree_top"
// CHECK: "settings": [
// CHECK-NEXT: "Time"
