// A requested texture that no file defines is not the front end's error (the graph library
// reports it at its graph.json line); it is just absent from the signatures.
// RUN: texcc-fe %s --texture nothere --texture here | FileCheck %s

float here(float x) { return x; }
// CHECK-LABEL: // texcc-fe signatures:
// CHECK-NOT: not{{here}}
// CHECK: "here": {
// CHECK-NOT: not{{here}}
