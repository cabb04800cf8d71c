// A `for` whose trip count the front end knows (integer constants, ++/--, a counter the body
// only reads) is charged once before it runs and its condition carries no test; any other
// loop ticks per iteration. A constant loop with a literal start declares its charge first and
// starts at its last value without the budget (one iteration that records the fault); the
// empty branch of the `if` form comes first so that a following `else` keeps its `if`.
// RUN: texcc-fe %s | FileCheck %s

float f(int n, int k) {
  float s = 0.0f;
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 3u, __LINE__), d = texcc_bad ? (1) : (-1); d <= 1; ++d) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  for (int d = -1; d <= 1; ++d)
    s += (float)d;
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 8u, __LINE__), i = texcc_bad ? (1) : (8); i > 0; i--) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  for (int i = 8; i > 0; i--)
    s += 1.0f;
  // CHECK: {{^}}  if (k) if (!texcc_loop_charge(texcc_ctx, 0u, __LINE__)) {} else for (int i = 4; i < 2; ++i) s += 1.0f; else s = 2.0f;
  if (k) for (int i = 4; i < 2; ++i) s += 1.0f; else s = 2.0f;
  // The body writes the counter: per iteration.
  // CHECK: {{^}}  for (int i = 0; (i < 10) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < 10; ++i)
    i += k;
  // The bound is a parameter: charged its span (loop-budget-invariant.cl).
  // CHECK: {{^}}  if (!texcc_loop_charge_span(texcc_ctx, (long)(n) - (long)(0), __LINE__)) {} else for (int i = 0; i < n; ++i)
  for (int i = 0; i < n; ++i)
    s += 1.0f;
  // Counting up to a bound below the start with !=: would not end, per iteration.
  // CHECK: {{^}}  for (int i = 5; (i != 2) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 5; i != 2; ++i)
    s += 1.0f;
  // The counter's address is taken: per iteration.
  // CHECK: {{^}}  for (int i = 0; (i < 3) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i < 3; ++i) {
    int *p = &i;
    s += (float)*p;
  }
  return s;
}
