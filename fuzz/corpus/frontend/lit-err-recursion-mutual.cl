// Mutual recursion is rejected at the call that closes the cycle, naming the cycle.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float odd(int n);
float even(int n) { return n == 0 ? 1.0f : odd(n - 1); }
// CHECK: err-recursion-mutual.cl:[[@LINE+1]]:43: error: recursion is not allowed in texture code: 'even' -> 'odd' -> 'even'
float odd(int n) { return n == 0 ? 0.0f : even(n - 1); }
