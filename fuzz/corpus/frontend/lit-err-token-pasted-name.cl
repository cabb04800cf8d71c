// A function whose name is made by ## token pasting cannot be renamed where it is spelled.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

#define NAMED(a) a##_fn
// CHECK: err-token-pasted-name.cl:[[@LINE+1]]:7: error: cannot rename 'my_fn': its name is made by token pasting; spell the name in the source
float NAMED(my)(float x) { return x; }
