// A `for` whose bound the loop does not change (fbm's octaves, a ramp's stop count) is charged
// its span once before it runs, `max(0, B - A - K)` for `for (int i = A; i + K < B; ++i)` (and
// `A + K - B` counting down with `>`), so that its iterations carry no test; when the bound or
// the start could change while the loop runs, the loop ticks per iteration.
// RUN: texcc-fe %s | FileCheck %s

int clampCount(int n) { return n < 1 ? 1 : n; }

float f(int n, int k, __global const float4 *stops, int count) {
  float s = 0.0f;
  int m = clampCount(n);
  // CHECK: {{^}}  if (!texcc_loop_charge_span(texcc_ctx, (long)(m) - (long)(0), __LINE__)) {} else for (int i = 0; i < m; ++i)
  for (int i = 0; i < m; ++i)
    s += 1.0f;
  // An early return: charged the whole span all the same (the budget bounds, it does not count).
  // CHECK: {{^}}  if (!texcc_loop_charge_span(texcc_ctx, (long)(count) - (long)(0) - 1, __LINE__)) {} else for (int i = 0; i + 1 < count; ++i) {
  for (int i = 0; i + 1 < count; ++i) {
    if (stops[i].x > 1.0f)
      return s;
  }
  // CHECK: {{^}}  if (!texcc_loop_charge_span(texcc_ctx, (long)(n + 2) - (long)(m - 1), __LINE__)) {} else for (int i = n + 2; i > m - 1; --i)
  for (int i = n + 2; i > m - 1; --i)
    s += 2.0f;
  // The body writes the bound: per iteration.
  // CHECK: {{^}}  for (int i = 0; (i < n) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < n; ++i)
    n = 2;
  // An unsigned comparison (-1 < 2u is false): per iteration.
  // CHECK: {{^}}  for (int i = 0; (i < (unsigned)k) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < (unsigned)k; ++i)
    s += 1.0f;
  // A call in the bound (it could have effects): per iteration.
  // CHECK: {{^}}  for (int i = 0; (i < {{.*}}clampCount(TEXCC_CTX_ARG, k)) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < clampCount(k); ++i)
    s += 1.0f;
  // <= with a bound that could be INT_MAX (the loop would not end): per iteration.
  // CHECK: {{^}}  for (int i = 0; (i <= k) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i <= k; ++i)
    s += 1.0f;
  // The bound's address is taken (a write through the pointer would change it): per iteration.
  int *p = &k;
  // CHECK: {{^}}  for (int i = 0; (i < k) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < k; ++i)
    *p = 1;
  return s;
}
