// The rendered code starts with a #line directive naming the user's file, and keeps every line
// at its number (the checked line below is this file's line 6).
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}#line 1 "{{.*}}line-directive.cl"{{$}}
float f(float x) { return x; }
// CHECK-NEXT: // The rendered code starts
