// A call whose callee name and '(' come from different macro expansions cannot get the context.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

#define CALLEE(f) f
float g(float x) { return x; }
// CHECK: err-macro-split-call.cl:[[@LINE+1]]:34: error: cannot pass the hit context to 'g': its name and its '(' come from different macro expansions
float h(float x) { return CALLEE(g)(x); }
