// A user header is spliced into the file's section, rewritten with the file's prefix and framed
// by #line directives, so that the kernel needs no include path; a second (guarded) include
// adds nothing. System headers would stay #include lines.
// RUN: texcc-fe %s -I %inputs/frontend/include > %t.cl
// RUN: FileCheck %s < %t.cl
// RUN: sh %inputs/frontend/syntax-check.sh %clang %t.cl

#include "common.h"
#include "common.h"
float shade(float x) { return gainOf(x); }
// CHECK: {{^}}#line 1 "{{.*}}include{{/|\\}}common.h"
// CHECK: {{^}}TEXCC_FN float include_splice_gainOf(TEXCC_CTX_PARAM, float x) { return x * COMMON_GAIN; }
// CHECK: {{^}}#line 9 "{{.*}}include-splice.cl"{{$}}
// CHECK-EMPTY:
// CHECK-NEXT: {{^}}TEXCC_FN float include_splice_shade(TEXCC_CTX_PARAM, float x) { return include_splice_gainOf(TEXCC_CTX_ARG, x); }
// CHECK: {{^}}#undef COMMON_H
// CHECK-NEXT: {{^}}#undef COMMON_GAIN
