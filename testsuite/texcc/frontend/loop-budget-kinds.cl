// Every loop's condition ends with one iteration of the work-item's loop budget (the
// condition first: an iteration that the condition ends does not count); an empty `for`
// condition becomes the budget alone; a do-while is bounded at its test.
// RUN: texcc-fe %s | FileCheck %s

float f(int n) {
  float s = 0.0f;
  // CHECK: {{^}}  for (int i = 0; (i * i < n) && texcc_loop_continues(texcc_ctx, __LINE__); ++i)
  for (int i = 0; i * i < n; ++i)
    s += 1.0f;
  // CHECK: {{^}}  while ((s > 2.0f) && texcc_loop_continues(texcc_ctx, __LINE__))
  while (s > 2.0f)
    s -= 1.0f;
  // CHECK: {{^}}  do { s += 0.5f; } while ((s < 4.0f) && texcc_loop_continues(texcc_ctx, __LINE__));
  do { s += 0.5f; } while (s < 4.0f);
  // CHECK: {{^}}  for (; texcc_loop_continues(texcc_ctx, __LINE__);)
  for (;;)
    break;
  return s;
}
