// Direct recursion is rejected at the recursive call.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float fact(float n) {
  // CHECK: err-recursion-direct.cl:[[@LINE+1]]:29: error: recursion is not allowed in texture code: 'fact' -> 'fact'
  return n <= 1.0f ? 1.0f : fact(n - 1.0f) * n;
}
